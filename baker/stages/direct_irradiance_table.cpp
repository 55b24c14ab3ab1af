#include <omp.h>

#include <algorithm>

#include "baker/stages/direct_irradiance_table.h"

namespace skybake {

Texture2D computeDirectIrradianceTable(const StageContext& ctx, const Texture2D& optical_depth) {
  const TextureSizes& s = ctx.sampler.sizes();
  Texture2D table(s.irradiance_mu_s, s.irradiance_r);
  const double alpha = ctx.atmosphere.sun_angular_radius_rad;
#pragma omp parallel for schedule(dynamic)
  for (int i_r = 0; i_r < table.height; ++i_r) {
    for (int i_mu_s = 0; i_mu_s < table.width; ++i_mu_s) {
      const RMuS rm = irradianceTexelConfig(ctx.sampler.domain(), table.width, table.height, i_mu_s, i_r);
      // As Sky::irradiance counts the sun on a horizontal surface: the part of
      // the disk above the planet's horizon, times the cosine of its centre.
      table.at(i_mu_s, i_r) = ctx.atmosphere.sun_irradiance *
                              ctx.sampler.transmittanceToSun(optical_depth, rm.r, rm.mu_s, alpha) *
                              static_cast<float>(std::max(rm.mu_s, 0.0));
    }
    ctx.progress.advance(1);
  }
  return table;
}

}  // namespace skybake
