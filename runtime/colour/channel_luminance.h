// Luminance of a bake's channel values, as one weight per channel.
#pragma once

#include <vector>

#include "data_formats/config/atmosphere_parameters.h"
#include "data_formats/spectra/spectrum.h"

namespace skybake::colour {

// What one unit of each channel adds to luminance (cd m^-2 per unit of
// radiance; for irradiance the same weights give illuminance in lx):
//  - CIE XYZ channels (W m^-2 sr^-1): 683 lm/W on Y, 0 on X and Z;
//  - wavelength channels (W m^-2 sr^-1 nm^-1): 683 lm/W times each
//    wavelength's ybar weight in SpectralToXyz, the piecewise-linear
//    spectrum through the channels that `skybake render` turns into colour
//    (a one-wavelength bake is flat: 683 times the integral of ybar).
// Lanes past the bake's channels are 0, so the luminance of a Spectrum is
// glm::dot(weights, value).
// A spectral atmosphere (more than 4 wavelengths) has no lanes for them:
// its weights are 0 here, wavelengthLuminanceWeights gives them.
Spectrum luminanceWeights(const AtmosphereParameters& a);

// The wavelength channels' weights above for any number of wavelengths, in
// their order: 683 lm/W times each one's ybar weight in SpectralToXyz.
std::vector<float> wavelengthLuminanceWeights(const std::vector<double>& wavelengths_nm);

}  // namespace skybake::colour
