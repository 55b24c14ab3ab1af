// Luminance of a bake's channel values, as one weight per channel.
#pragma once

#include "data_formats/atmosphere_parameters.h"
#include "data_formats/spectrum.h"

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
Spectrum luminanceWeights(const AtmosphereParameters& a);

}  // namespace skybake::colour
