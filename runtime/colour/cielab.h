// CIE 1976 L*a*b* (CIELAB) from CIE XYZ relative to a reference white
// (CIE 015:2018, section 8.2.1).
#pragma once

#include <cmath>

#include "runtime/colour/spectral_to_xyz.h"
#include "runtime/colour/srgb_primaries.h"

namespace skybake::colour {

struct Lab {
  double l = 0.0, a = 0.0, b = 0.0;
};

// The white point of sRGB and Rec. 709 (D65, from its chromaticity in
// srgb_primaries.h) at Y = 1: the white the images of `skybake render` are
// shown against.
inline Xyz srgbWhiteXyz() {
  const Chromaticity& w = kSrgbChromaticities.white;
  return {w.x / w.y, 1.0, (1.0 - w.x - w.y) / w.y};
}

// CIELAB's compressive function: a cube root, a straight line below
// (6/29)^3 so that black has a finite slope (CIE 015's definition).
inline double cielabF(double t) {
  constexpr double kDelta = 6.0 / 29.0;
  return t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
}

inline Lab labFromXyz(const Xyz& xyz, const Xyz& white) {
  const double fx = cielabF(xyz.x / white.x), fy = cielabF(xyz.y / white.y), fz = cielabF(xyz.z / white.z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

}  // namespace skybake::colour
