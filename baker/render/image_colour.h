// The colour of an image's pixels: each pixel's spectrum (its bake's
// wavelengths) to CIE XYZ by the CIE 1931 observer, then to linear sRGB
// (Rec. 709 primaries, D65 white); see runtime/colour/.
#pragma once

#include <vector>

#include "baker/render/sky_image.h"
#include "runtime/colour/srgb_primaries.h"

namespace skybake {

// What one unit of each channel of a bake with these channels adds to an
// image's linear sRGB, times `scale`: its wavelength's share of X, Y, Z
// among all the bake's wavelengths (CIE 1931), or for a colour bake its X,
// Y or Z, through the sRGB primaries. The conversion is linear, so a
// pixel's colour is the sum over its channels (linearSrgbImage; the
// browser viewer does the same sum in its shader).
std::vector<colour::LinearRgb> linearSrgbPerChannel(const AtmosphereParameters& channels, double scale);

// Linear sRGB, 3 floats per pixel, rows top to bottom, of an image of a
// bake with these channels (linearSrgbPerChannel): XYZ of spectral radiance
// (W m^-2 sr^-1 nm^-1 integrated over nm: W m^-2 sr^-1), or a colour bake's
// X, Y, Z as they are, times `scale`. A scale of 683 lm/W
// (colour::kMaxLuminousEfficacy_lm_per_W) gives cd m^-2: Y = 0.2126 R +
// 0.7152 G + 0.0722 B is luminance.
std::vector<float> linearSrgbImage(const SpectralImage& image, const AtmosphereParameters& channels, double scale);
// The same for channels that are these wavelengths.
std::vector<float> linearSrgbImage(const SpectralImage& image, const std::vector<double>& wavelengths_nm, double scale);

// The scale that makes a preview's linear sRGB keep `--exposure`'s meaning
// of a multiplier on spectral radiance in W m^-2 sr^-1 nm^-1: Y is the
// spectrum's ybar-weighted mean, so a flat spectrum of 1 / exposure
// W m^-2 sr^-1 nm^-1 has Y = 1 after exposure.
double previewScalePerExposure();

}  // namespace skybake
