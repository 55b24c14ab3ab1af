// Transmittance along a straight segment.
#include <algorithm>

#include <glm/geometric.hpp>

#include "runtime/lookup_geometry.h"
#include "runtime/sky.h"
#include "runtime/sky_lookup_constants.h"
#include "runtime/sky_lookup_start.h"

namespace skybake {
namespace {

bool grazesGround(const AtmosphereDomain& domain, const AtmosphereRay& ray) {
  const double closest_approach_m = ray.r * safeSqrt(1.0 - ray.mu * ray.mu);
  return closest_approach_m >= domain.bottom_radius_m - kGroundGrazeTolerance_m;
}

}  // namespace

Spectrum Sky::transmittance(const glm::dvec3& a_given, const glm::dvec3& b_given) const {
  const glm::dvec3 a = lookupPosition(a_given, "a");
  const glm::dvec3 b = lookupPosition(b_given, "b");
  requireOneLaneGroup("transmittance");
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
