// Where every Sky lookup starts: the camera, or where its ray enters the
// atmosphere (a camera in space is moved along its ray to the top).
#pragma once

#include <glm/vec3.hpp>

#include "data_formats/parameterization/texture_mapping.h"
#include "runtime/physics/atmosphere_ray.h"

namespace skybake {

inline AtmosphereRay enterAtmosphere(const AtmosphereDomain& domain, const glm::dvec3& camera, const glm::dvec3& dir) {
  return atmosphereRay(domain.bottom_radius_m, domain.top_radius_m, camera, dir, 0.0);
}

}  // namespace skybake
