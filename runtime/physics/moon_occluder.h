// A moon that passes in front of the sun: a sphere given by its centre
// (metres from the planet's centre, like cameras) and radius. Seen from a
// point, it covers part of the sun disk: how much depends on the point,
// because the moon is near (its direction and angular radius change across
// the planet by a degree and a few percent), which is what confines totality
// to a narrow umbra. Every user (the runtime's eclipse lookups, the
// reference solver, skybake render) asks Moon::visibleSunFraction, whose
// formula is the kernel runtime/kernel/moon_occlusion.glsl, which the
// shaders share.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "data_formats/angles.h"
#include "data_formats/kernel/kernel_language.h"

namespace skybake {
namespace kernel {
#include "runtime/kernel/moon_occlusion.glsl"
}  // namespace kernel

// The mean Earth-Moon distance (centre to centre), m: where the convenience
// form puts the moon, so its angular radius means what an observer sees.
inline constexpr double kMeanLunarDistance_m = 384'400e3;
// The Moon's mean radius, m.
inline constexpr double kMoonRadius_m = 1'737.4e3;

// The circle-circle lens and the sun's fraction past a moon's disc.
inline constexpr auto& discOverlapArea = kernel::skybakeDiscOverlapArea;
inline constexpr auto& sunFractionPastMoonDisc = kernel::skybakeSunFractionPastMoonDisc;

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
  // the moon (kernel::skybakeMoonVisibleSunFraction).
  double visibleSunFraction(const glm::dvec3& point, const glm::dvec3& sun_dir, double sun_radius_rad) const {
    return kernel::skybakeMoonVisibleSunFraction(centre_m, radius_m, point, sun_dir, sun_radius_rad);
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
