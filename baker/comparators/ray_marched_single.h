// The common shader approach: single scattering ray-marched per view ray, 32
// uniform steps along the view and 8 toward the sun at each, Rayleigh + Mie +
// absorption. The ground is lit by the sun alone (no skylight).
#pragma once

#include "baker/comparators/sky_method.h"

namespace skybake {

class RayMarchedSingleScattering final : public SkyMethod {
 public:
  explicit RayMarchedSingleScattering(const AtmosphereParameters& a) : a_(a) {}
  std::string name() const override { return "ray-marched single scattering (32 x 8 steps)"; }
  RadianceAndTransmittance received(const glm::dvec3& camera, const glm::dvec3& view,
                                    const glm::dvec3& sun) const override;

 private:
  AtmosphereParameters a_;
};

}  // namespace skybake
