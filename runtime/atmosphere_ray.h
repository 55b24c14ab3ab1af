// A ray in the spherical shell of the atmosphere: where it starts inside (a
// camera in space is moved to where its ray enters, one below the ground is
// put on the ground directly above), how far it goes and what it ends on.
// Lookups, the reference solver and the comparators all start rays here.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "data_formats/ray_sphere.h"

namespace skybake {

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
// A start below the ground is put on the ground directly above.
inline AtmosphereRay atmosphereRay(double bottom, double top, glm::dvec3 start, const glm::dvec3& dir,
                                   double max_length) {
  AtmosphereRay ray;
  double r = glm::length(start);
  if (r < bottom) {
    start = r > 0.0 ? start * (bottom / r) : glm::dvec3(0.0, 0.0, bottom);
    r = bottom;
  }
  double rmu = glm::dot(start, dir);
  if (r > top) {
    // top^2 minus the squared distance of the ray's line from the centre,
    // taken from the line's point nearest the centre: rmu^2 - r^2 + top^2
    // cancels for a far camera (at 1e12 m rmu^2 and r^2 are 1e24, rounded
    // by 1e8 m^2, an error of 14 km along a grazing ray).
    const glm::dvec3 nearest = start - dir * rmu;
    const double discriminant = top * top - glm::dot(nearest, nearest);
    const double entry = -rmu - safeSqrt(discriminant);
    if (discriminant < 0.0 || entry < 0.0) return ray;
    start += dir * entry;
    ray.moved = entry;
    r = top;
    rmu += entry;
  }
  ray.inside = true;
  ray.origin = start;
  ray.dir = dir;
  ray.r = r;
  ray.mu = clampCosine(rmu / r);
  ray.ends_on_ground = rayIntersectsSphere(r, ray.mu, bottom);
  ray.length = distanceToAtmosphereEnd(r, ray.mu, bottom, top, ray.ends_on_ground);
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
