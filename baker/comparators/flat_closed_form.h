// Closed-form single scattering for a flat, exponentially stratified,
// infinite atmosphere, no ray marching. For a camera at altitude h looking up
// at cosine v, sun at cosine s, and constituent i with scattering column
// c_i = beta_i H_i exp(-h / H_i) above the camera:
//   L = E sum_i P_i(nu) (c_i / B) s (exp(-B/s) - exp(-B/v)) / (s - v),
// with B the total extinction column above the camera. Exact when all
// constituents share one scale height; absorption layers enter B as an
// exponential of Rayleigh's scale height. Views below the horizontal are
// treated as 1 deg above it (a flat atmosphere has no ground in sight), and a
// sun below the horizon gives no light.
#pragma once

#include "baker/comparators/sky_method.h"

namespace skybake {

class FlatClosedFormSingleScattering final : public SkyMethod {
 public:
  explicit FlatClosedFormSingleScattering(const AtmosphereParameters& a);
  std::string name() const override { return "closed-form flat single scattering"; }
  RadianceAndTransmittance received(const glm::dvec3& camera, const glm::dvec3& view,
                                    const glm::dvec3& sun) const override;

 private:
  AtmosphereParameters a_;
  double rayleigh_scale_height_m_;
  double mie_scale_height_m_;
};

}  // namespace skybake
