// Sun and sky irradiance on a surface.
#include <algorithm>

#include <glm/geometric.hpp>

#include "data_formats/error.h"
#include "runtime/sky.h"

namespace skybake {

SunAndSkyIrradiance Sky::irradiance(const glm::dvec3& point, const glm::dvec3& normal,
                                    const glm::dvec3& sun_dir) const {
  if (!outputs().ground_irradiance) {
    throw Error(ErrorKind::BadInput,
                "irradiance: this bake leaves it out (its scene.outputs lacks \"ground_irradiance\")");
  }
  const AtmosphereDomain& domain = sampler_.domain();
  const double length = glm::length(point);
  const double r = std::clamp(length, domain.bottom_radius_m, domain.top_radius_m);
  const glm::dvec3 up = length > 0.0 ? point / length : glm::dvec3(0.0, 0.0, 1.0);
  const double mu_s = clampCosine(glm::dot(up, sun_dir));
  const BakeTables& t = bake_.tables;
  const Spectrum sky =
      sampler_.irradiance(t.irradiance, r, mu_s) * static_cast<float>(0.5 * (1.0 + glm::dot(normal, up)));
  const Spectrum sun = atmosphere().sun_irradiance *
                       sampler_.transmittanceToSun(t.optical_depth, r, mu_s, atmosphere().sun_angular_radius_rad) *
                       static_cast<float>(std::max(glm::dot(normal, sun_dir), 0.0));
  return {sun, sky};
}

}  // namespace skybake
