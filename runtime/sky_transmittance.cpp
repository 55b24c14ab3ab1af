// Transmittance along a straight segment.
#include <algorithm>

#include <glm/geometric.hpp>

#include "runtime/sky.h"
#include "runtime/sky_lookup_start.h"

namespace skybake {
namespace {

// A ray whose closest approach to the planet centre lies within this distance
// below the ground only grazes it. Points along an exactly tangent ray give
// directions that differ by rounding (~1e-16 rad), so the same ray was
// classified as hitting the ground or not from one point to the next, and the
// transmittance to points past the tangent point flickered between 0 and its
// value. 1 mm is far above that rounding (~1e-6 m at 1e10 m) and far below
// any geometry a renderer resolves.
constexpr double kGroundGrazeTolerance_m = 1e-3;

bool grazesGround(const AtmosphereDomain& domain, const AtmosphereRay& ray) {
  const double closest_approach_m = ray.r * safeSqrt(1.0 - ray.mu * ray.mu);
  return closest_approach_m >= domain.bottom_radius_m - kGroundGrazeTolerance_m;
}

}  // namespace

Spectrum Sky::transmittance(const glm::dvec3& a, const glm::dvec3& b) const {
  const AtmosphereDomain& domain = sampler_.domain();
  const glm::dvec3 offset = b - a;
  const double distance = glm::length(offset);
  if (!(distance > 0.0)) return Spectrum(1.0f);
  const glm::dvec3 dir = offset / distance;
  const AtmosphereRay start = enterAtmosphere(domain, a, dir);
  const double d = distance - start.moved;
  if (!start.inside || d <= 0.0) return Spectrum(1.0f);
  bool ground = start.ends_on_ground;
  double length = start.length;
  if (ground && d > length) {
    if (!grazesGround(domain, start)) return Spectrum(0.0f);  // the segment passes through the planet
    // Tangent to the ground: the segment goes on past the tangent point.
    ground = false;
    length = distanceToOuterSphere(start.r, start.mu, domain.top_radius_m);
  }
  // Beyond the top the ray is in vacuum: only the part inside counts.
  const double inside = std::min(d, length);
  return glm::exp(-sampler_.opticalDepthAlongRay(bake_.tables.optical_depth, start.r, start.mu, inside, ground));
}

}  // namespace skybake
