// A ray in the spherical shell of the atmosphere: where it starts inside (a
// camera in space is moved to where its ray enters, one below the ground is
// put on the ground directly above), how far it goes and what it ends on.
// Lookups, the reference solver and the comparators all start rays here.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "data_formats/parameterization/ray_sphere.h"

namespace skybake {
namespace kernel {
#include "runtime/kernel/atmosphere_entry.glsl"
}  // namespace kernel

struct AtmosphereRay {
  bool inside = false;  // false: the ray misses the atmosphere
  glm::dvec3 origin;    // in the atmosphere (moved in from space if needed)
  glm::dvec3 dir;
  double r = 0.0;       // |origin|
  double mu = 0.0;      // zenith cosine of dir at origin
  double length = 0.0;  // to its end: the ground, the top or a distance limit
  bool ends_on_ground = false;
  double moved = 0.0;  // distance from the given start to origin
};

// The ray from `start` along unit `dir`, limited to `max_length` (<= 0: none).
// A start below the ground is put on the ground directly above; one in space
// is moved to where the ray enters (the kernel
// runtime/kernel/atmosphere_entry.glsl, which the shaders share).
inline AtmosphereRay atmosphereRay(double bottom, double top, glm::dvec3 start, const glm::dvec3& dir,
                                   double max_length) {
  AtmosphereRay ray;
  const kernel::SkybakeRay entered = kernel::skybakeEnterAtmosphere(bottom, top, start, dir);
  if (!entered.inside) return ray;
  ray.inside = true;
  ray.origin = entered.origin;
  ray.dir = dir;
  ray.r = entered.r;
  ray.mu = entered.mu;
  ray.length = entered.length_m;
  ray.ends_on_ground = entered.ends_on_ground;
  ray.moved = entered.moved_m;
  if (max_length > 0.0) {
    const double limit = max_length - ray.moved;
    if (limit <= 0.0) {
      ray.inside = false;
      return ray;
    }
    if (limit < ray.length) {
      ray.length = limit;
      ray.ends_on_ground = false;
    }
  }
  return ray;
}

}  // namespace skybake
