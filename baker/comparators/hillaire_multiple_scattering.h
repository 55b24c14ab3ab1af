// Hillaire (2020) style: a transmittance table plus a 2D multiple-scattering
// table (altitude x sun cosine) built with an isotropic phase function and the
// geometric series 1 / (1 - f_ms) for all orders past the second, then per
// view ray a 32-step ray march of single scattering plus sigma_s times the
// table's multiple-scattering term.
#pragma once

#include "baker/comparators/sky_method.h"
#include "data_formats/bake_file/textures.h"
#include "runtime/tables/table_sampler.h"

namespace skybake {

class HillaireMultipleScattering final : public SkyMethod {
 public:
  explicit HillaireMultipleScattering(const AtmosphereParameters& a);
  std::string name() const override { return "transmittance + 2D multiple-scattering tables (Hillaire 2020)"; }
  RadianceAndTransmittance received(const glm::dvec3& camera, const glm::dvec3& view,
                                    const glm::dvec3& sun) const override;
  double precomputeSeconds() const override { return precompute_seconds_; }
  size_t memoryBytes() const override;

 private:
  Spectrum transmittanceToSun(const glm::dvec3& p, const glm::dvec3& sun) const;
  // Radiance of the Lambertian ground at `ground_point` per unit sun irradiance.
  SpectrumD litGround(const glm::dvec3& ground_point, const glm::dvec3& sun) const;
  Spectrum multipleScattering(double altitude, double mu_s) const;

  AtmosphereParameters a_;
  TextureSizes sizes_;
  TableSampler sampler_;
  Texture2D optical_depth_;
  Texture2D multiple_;  // x: sun cosine, y: altitude; per unit sun irradiance
  double precompute_seconds_ = 0.0;
};

}  // namespace skybake
