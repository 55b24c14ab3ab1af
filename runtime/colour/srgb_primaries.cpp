#include "runtime/colour/srgb_primaries.h"

namespace skybake::colour {
namespace {

Matrix3 inverse(const Matrix3& m) {
  const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
  Matrix3 r;
  r[0] = {c00 / det, (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det, (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det};
  r[1] = {c01 / det, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det, (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det};
  r[2] = {c02 / det, (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det, (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det};
  return r;
}

// XYZ with Y = 1 of chromaticity (x, y).
std::array<double, 3> unitLuminanceXyz(const Chromaticity& c) { return {c.x / c.y, 1.0, (1.0 - c.x - c.y) / c.y}; }

// The primaries' XYZ, each scaled so that their sum is the white point.
Matrix3 xyzFromRgb(const RgbChromaticities& p) {
  const std::array<double, 3> r = unitLuminanceXyz(p.red), g = unitLuminanceXyz(p.green), b = unitLuminanceXyz(p.blue);
  const Matrix3 primaries = {{{r[0], g[0], b[0]}, {r[1], g[1], b[1]}, {r[2], g[2], b[2]}}};
  const Matrix3 to_intensities = inverse(primaries);
  const std::array<double, 3> w = unitLuminanceXyz(p.white);
  Matrix3 m;
  for (int column = 0; column < 3; ++column) {
    const double scale =
        to_intensities[column][0] * w[0] + to_intensities[column][1] * w[1] + to_intensities[column][2] * w[2];
    for (int row = 0; row < 3; ++row) m[row][column] = primaries[row][column] * scale;
  }
  return m;
}

}  // namespace

const Matrix3& xyzFromLinearSrgbMatrix() {
  static const Matrix3 m = xyzFromRgb(kSrgbChromaticities);
  return m;
}

const Matrix3& linearSrgbFromXyzMatrix() {
  static const Matrix3 m = inverse(xyzFromLinearSrgbMatrix());
  return m;
}

LinearRgb linearSrgbFromXyz(const Xyz& v) {
  const Matrix3& m = linearSrgbFromXyzMatrix();
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

Xyz xyzFromLinearSrgb(const LinearRgb& v) {
  const Matrix3& m = xyzFromLinearSrgbMatrix();
  return {m[0][0] * v.r + m[0][1] * v.g + m[0][2] * v.b, m[1][0] * v.r + m[1][1] * v.g + m[1][2] * v.b,
          m[2][0] * v.r + m[2][1] * v.g + m[2][2] * v.b};
}

}  // namespace skybake::colour
