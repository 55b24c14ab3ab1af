// The linear sRGB / Rec. 709 colour space: its primaries and white point
// (IEC 61966-2-1:1999 and ITU-R BT.709-6: red (0.64, 0.33), green
// (0.30, 0.60), blue (0.15, 0.06), white D65 (0.3127, 0.3290)) and the
// matrices between it and CIE XYZ, derived from those chromaticities so
// that the white point's XYZ with Y = 1 is RGB (1, 1, 1).
#pragma once

#include <array>

#include "runtime/colour/spectral_to_xyz.h"

namespace skybake::colour {

struct Chromaticity {
  double x, y;
};

struct RgbChromaticities {
  Chromaticity red, green, blue, white;
};

inline constexpr RgbChromaticities kSrgbChromaticities{{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, {0.3127, 0.3290}};

struct LinearRgb {
  double r = 0.0, g = 0.0, b = 0.0;
};

// Rows are the output's components, columns the input's.
using Matrix3 = std::array<std::array<double, 3>, 3>;

// XYZ of each sRGB primary at unit intensity, as columns (X, Y, Z rows);
// its middle row is the luminance weights 0.2126, 0.7152, 0.0722.
const Matrix3& xyzFromLinearSrgbMatrix();
// The inverse: linear sRGB from XYZ.
const Matrix3& linearSrgbFromXyzMatrix();

// Linear sRGB in the unit of Y. Colours outside the sRGB gamut (the deepest
// blue of a clear sky can be) have a negative component; they are kept so
// that Y, and so luminance, stays exact.
LinearRgb linearSrgbFromXyz(const Xyz& xyz);
Xyz xyzFromLinearSrgb(const LinearRgb& rgb);

}  // namespace skybake::colour
