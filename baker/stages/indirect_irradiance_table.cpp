#include <omp.h>

#include "baker/stages/indirect_irradiance_table.h"

namespace skybake {
namespace {

// Midpoint grid over the upper hemisphere: 32 zenith x 64 azimuth directions.
constexpr int kZenithSamples = 32;
constexpr int kAzimuthSamples = 2 * kZenithSamples;

}  // namespace

Texture2D computeIndirectIrradianceTable(const StageContext& ctx, const OrderRadiance& order) {
  const TextureSizes& s = ctx.sampler.sizes();
  const AtmosphereParameters& a = ctx.atmosphere;
  Texture2D table(s.irradiance_mu_s, s.irradiance_r);
  const double d_theta = kPi / 2.0 / kZenithSamples;
  const double d_phi = 2.0 * kPi / kAzimuthSamples;
#pragma omp parallel
  {
    // The directions of one zenith ring share (r, mu, mu_s): the tables are
    // interpolated there once and each azimuth only blends across nu.
    OrderRadianceAlongNu ring_radiance(order, ctx.sampler, a.mie_phase_g);
#pragma omp for schedule(dynamic)
    for (int i_r = 0; i_r < table.height; ++i_r) {
      for (int i_mu_s = 0; i_mu_s < table.width; ++i_mu_s) {
        const RMuS rm = irradianceTexelConfig(ctx.sampler.domain(), table.width, table.height, i_mu_s, i_r);
        const double sun_x = safeSqrt(1.0 - rm.mu_s * rm.mu_s);
        SpectrumD sum(0.0);
        for (int i = 0; i < kZenithSamples; ++i) {
          const double theta = (i + 0.5) * d_theta;
          const double mu = std::cos(theta);
          // cos(theta) for the horizontal surface times the solid angle element.
          const double weight = mu * std::sin(theta) * d_theta * d_phi;
          ring_radiance.moveTo(rm.r, mu, rm.mu_s, false);
          for (int j = 0; j < kAzimuthSamples; ++j) {
            const double phi = (j + 0.5) * d_phi;
            const double nu = clampCosine(std::sin(theta) * std::cos(phi) * sun_x + mu * rm.mu_s);
            sum += SpectrumD(ring_radiance.at(nu)) * weight;
          }
        }
        table.at(i_mu_s, i_r) = Spectrum(sum);
      }
      ctx.progress.advance(1);
    }
  }
  return table;
}

}  // namespace skybake
