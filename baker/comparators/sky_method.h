// A way to get sky radiance, for `skybake compare`: the bake, or one of the
// simpler methods people use instead. Each answers the same queries as the
// reference, so their errors and costs line up in one table.
#pragma once

#include <cstddef>
#include <string>

#include <glm/vec3.hpp>

#include "runtime/sky.h"

namespace skybake {

class SkyMethod {
 public:
  virtual ~SkyMethod() = default;
  virtual std::string name() const = 0;
  // What the viewer receives along the ray (in-scattering plus the lit ground
  // for rays that end on it), and the transmittance along it.
  virtual RadianceAndTransmittance received(const glm::dvec3& camera, const glm::dvec3& view,
                                            const glm::dvec3& sun) const = 0;
  virtual double precomputeSeconds() const { return 0.0; }  // tables built before the first ray
  virtual size_t memoryBytes() const { return 0; }          // tables kept for lookups
};

}  // namespace skybake
