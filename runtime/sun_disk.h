#pragma once

#include <algorithm>

namespace skybake {

// How much of the sun disk a point sees above the planet's horizon. The bake,
// the runtime and the reference solver all count the sun this way: the light
// arriving from the disk's centre, times this fraction (and, on a surface,
// times the cosine of the centre's direction). So the validation measures the
// bake's numerical error, not a difference between two models of the sun.

// Fraction of the sun disk above the horizon given how far (in cosine) its
// centre is above it and the disk's half-size in the same units: a smooth
// ramp over the disk's diameter, within 0.04 of the disk's exact area above a
// straight horizon. A point sun (half_size 0) is all up or all down. Written
// with selects rather than an early return, so loops over many suns
// vectorize.
inline double sunDiskVisibleFraction(double height, double half_size) {
  const double ramp = std::clamp((height + half_size) / (2.0 * half_size), 0.0, 1.0);
  const double point = height > 0.0 ? 1.0 : 0.0;
  const double t = half_size > 0.0 ? ramp : point;
  return t * t * (3.0 - 2.0 * t);  // smooth ramp: no kink in the sky's derivative
}

// The disk's half-size in zenith cosine near the horizon seen from radius
// r_m: its angular radius times the sine of the horizon's zenith angle,
// bottom_radius_m / r_m.
inline double sunDiskHalfSizeAtHorizon(double bottom_radius_m, double r_m, double sun_angular_radius_rad) {
  return bottom_radius_m / r_m * sun_angular_radius_rad;
}

}  // namespace skybake
