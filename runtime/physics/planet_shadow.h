// Where a ray crosses the edge of the planet's shadow: the kernel
// runtime/kernel/planet_shadow.glsl in double (it says why integrators
// split their rays there), the one source the shaders share.
#pragma once

#include <array>

#include <glm/vec3.hpp>

#include "data_formats/kernel/kernel_language.h"
#include "data_formats/parameterization/ray_sphere.h"

namespace skybake {
namespace kernel {
#include "runtime/kernel/planet_shadow.glsl"
}  // namespace kernel

struct ShadowCrossings {
  int count = 0;
  std::array<double, 2> distance{};  // ascending, each in (0, length)
  static ShadowCrossings of(const kernel::SkybakeShadowCrossings& k) {
    return {k.count, {k.distance_m.x, k.distance_m.y}};
  }
};

// Crossings of the shadow's edge by the segment origin + t dir, t in
// (0, length); `sun` is the unit vector toward the sun, positions are
// relative to the planet's centre.
inline ShadowCrossings planetShadowCrossings(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& sun,
                                             double bottom_radius, double length) {
  return ShadowCrossings::of(kernel::skybakePlanetShadowCrossingsOfSegment(origin, dir, sun, bottom_radius, length));
}

// The same for the ray from radius r at zenith cosine mu, the sun at zenith
// cosine mu_s making cosine nu with it, over (0, length).
inline ShadowCrossings planetShadowCrossings(double r, double mu, double mu_s, double nu, double bottom_radius,
                                             double length) {
  return ShadowCrossings::of(kernel::skybakePlanetShadowCrossings(r, mu, mu_s, nu, bottom_radius, length));
}

}  // namespace skybake
