// Sun and sky irradiance on a surface.
#include <algorithm>

#include <glm/geometric.hpp>

#include "data_formats/error.h"
#include "runtime/lookup_geometry.h"
#include "runtime/sky.h"

namespace skybake {

namespace {

// Where a surface point is for the irradiance lookups: its radius within
// the tables' domain and its local up.
struct SurfacePoint {
  double r;
  glm::dvec3 up;
};
SurfacePoint surfacePoint(const AtmosphereDomain& domain, const glm::dvec3& point) {
  const double length = glm::length(point);
  return {std::clamp(length, domain.bottom_radius_m, domain.top_radius_m),
          length > 0.0 ? point / length : glm::dvec3(0.0, 0.0, 1.0)};
}

}  // namespace

Spectrum Sky::sunIrradiance(const glm::dvec3& point_given, const glm::dvec3& normal_given, const Sunlight& sun) const {
  const auto [point, normal, sun_dir] = checkedSurface(point_given, normal_given, sun.direction);
  requireOneLaneGroup("sunIrradiance");
  const SurfacePoint p = surfacePoint(sampler_.domain(), point);
  const double mu_s = clampCosine(glm::dot(p.up, sun_dir));
  const Spectrum uneclipsed =
      atmosphere().sun_irradiance *
      sampler_.transmittanceToSun(bake_.tables.optical_depth, p.r, mu_s, atmosphere().sun_angular_radius_rad) *
      static_cast<float>(std::max(glm::dot(normal, sun_dir), 0.0));
  if (!eclipsed(sun)) return uneclipsed;
  return uneclipsed *
         static_cast<float>(sun.moon.visibleSunFraction(point, sun_dir, atmosphere().sun_angular_radius_rad));
}

SunAndSkyIrradiance Sky::irradiance(const glm::dvec3& point_given, const glm::dvec3& normal_given,
                                    const Sunlight& sun) const {
  if (eclipsed(sun)) return eclipsedIrradiance(point_given, normal_given, sun);
  const auto [point, normal, sun_dir] = checkedSurface(point_given, normal_given, sun.direction);
  requireOneLaneGroup("irradiance");
  if (!outputs().ground_irradiance) {
    throw Error(ErrorKind::BadInput,
                "irradiance: this bake leaves it out (its scene.outputs lacks \"ground_irradiance\")");
  }
  const SurfacePoint p = surfacePoint(sampler_.domain(), point);
  const double mu_s = clampCosine(glm::dot(p.up, sun_dir));
  const Spectrum sky = sampler_.irradiance(bake_.tables.irradiance, bake_.tables.optical_depth, p.r, mu_s) *
                       static_cast<float>(0.5 * (1.0 + glm::dot(normal, p.up)));
  return {sunIrradiance(point, normal, sun_dir), sky};
}

}  // namespace skybake
