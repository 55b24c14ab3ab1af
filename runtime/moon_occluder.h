// A moon that passes in front of the sun: a sphere given by its centre
// (metres from the planet's centre, like cameras) and radius. Seen from a
// point, it covers part of the sun disk: how much depends on the point,
// because the moon is near (its direction and angular radius change across
// the planet by a degree and a few percent), which is what confines totality
// to a narrow umbra. Every user (the runtime's eclipse lookups, the
// reference solver, skybake render) asks Moon::visibleSunFraction, the one
// place the occlusion is computed in C++; the GLSL library's
// skybakeMoonVisibleSunFraction (runtime/glsl/skybake_geometry.glsl) is the
// same formula in float, tied to this one by tests/gl's GlParity.Eclipse*.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "data_formats/angles.h"

namespace skybake {

// The mean Earth-Moon distance (centre to centre), m: where the convenience
// form puts the moon, so its angular radius means what an observer sees.
inline constexpr double kMeanLunarDistance_m = 384'400e3;
// The Moon's mean radius, m.
inline constexpr double kMoonRadius_m = 1'737.4e3;

// Area of the intersection of two discs of radii a and b whose centres are
// `separation` apart (same units; the exact circle-circle lens). Arguments
// to the inverse cosines are clamped: rounding near tangency would otherwise
// give NaN.
inline double discOverlapArea(double a, double b, double separation) {
  if (!(a > 0.0) || !(b > 0.0) || separation >= a + b) return 0.0;
  const double small = std::min(a, b);
  if (separation <= std::abs(a - b)) return kPi * small * small;
  const double d = separation;
  const double angle_a = std::acos(std::clamp((d * d + a * a - b * b) / (2.0 * d * a), -1.0, 1.0));
  const double angle_b = std::acos(std::clamp((d * d + b * b - a * a) / (2.0 * d * b), -1.0, 1.0));
  const double kite = std::max((-d + a + b) * (d + a - b) * (d - a + b) * (d + a + b), 0.0);
  return std::max(a * a * angle_a + b * b * angle_b - 0.5 * std::sqrt(kite), 0.0);
}

// Fraction of a sun disk of angular radius `sun_radius_rad` not covered by a
// moon disk of angular radius `moon_radius_rad` whose centre is
// `separation_rad` from the sun's: 1 with no overlap, 1 - (moon/sun)^2 at the
// centre of an annular eclipse, 0 in totality. The two discs are taken as
// flat, which for the sun's 0.27 deg is off by its angular radius squared
// (2e-5 relative). A point sun (radius 0) is all covered or all free.
inline double sunFractionPastMoonDisc(double sun_radius_rad, double moon_radius_rad, double separation_rad) {
  if (!(moon_radius_rad > 0.0)) return 1.0;
  if (!(sun_radius_rad > 0.0)) return separation_rad < moon_radius_rad ? 0.0 : 1.0;
  const double covered =
      discOverlapArea(sun_radius_rad, moon_radius_rad, separation_rad) / (kPi * sun_radius_rad * sun_radius_rad);
  return std::clamp(1.0 - covered, 0.0, 1.0);
}

struct Moon {
  glm::dvec3 centre_m{0.0};  // from the planet's centre
  double radius_m = 0.0;     // 0: no moon (nothing is occluded)

  bool present() const { return radius_m > 0.0; }

  // The moon seen from `camera` in unit direction `direction` with angular
  // radius `angular_radius_rad`, at the mean lunar distance from it.
  static Moon seenFrom(const glm::dvec3& camera, const glm::dvec3& direction, double angular_radius_rad) {
    return {camera + direction * kMeanLunarDistance_m, kMeanLunarDistance_m * std::sin(angular_radius_rad)};
  }

  // Fraction of the sun disk (unit direction `sun_dir` from every point, the
  // sun being far; angular radius `sun_radius_rad`) that `point` sees past
  // the moon. The separation comes from atan2 of the sine and cosine, which
  // keeps its precision at the small angles an eclipse is made of (an inverse
  // cosine loses it below 1e-4 rad). A point inside the moon sees nothing.
  double visibleSunFraction(const glm::dvec3& point, const glm::dvec3& sun_dir, double sun_radius_rad) const {
    if (!present()) return 1.0;
    const glm::dvec3 to_moon = centre_m - point;
    const double distance = glm::length(to_moon);
    if (!(distance > radius_m)) return 0.0;
    const double moon_radius_rad = std::asin(radius_m / distance);
    const double separation_rad = std::atan2(glm::length(glm::cross(to_moon, sun_dir)), glm::dot(to_moon, sun_dir));
    return sunFractionPastMoonDisc(sun_radius_rad, moon_radius_rad, separation_rad);
  }
};

// A moon seen along a view ray origin + t dir (origin in the atmosphere, in
// the planet-centred frame), for integrators that walk the ray by distance.
struct MoonAlongRay {
  Moon moon;
  glm::dvec3 origin{0.0}, dir{0.0, 0.0, 1.0}, sun_dir{0.0, 0.0, 1.0};
  double sun_radius_rad = 0.0;
  double visibleSunFraction(double t) const {
    return moon.visibleSunFraction(origin + dir * t, sun_dir, sun_radius_rad);
  }
};

}  // namespace skybake
