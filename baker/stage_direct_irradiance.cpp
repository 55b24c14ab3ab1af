#include <omp.h>

#include "baker/stages.h"

namespace skybake {

Texture2D computeDirectIrradianceTable(const StageContext& ctx, const Texture2D& optical_depth) {
  const TextureSizes& s = ctx.sampler.sizes();
  Texture2D table(s.irradiance_mu_s, s.irradiance_r);
  const double alpha = ctx.atmosphere.sun_angular_radius_rad;
#pragma omp parallel for schedule(dynamic)
  for (int i_r = 0; i_r < table.height; ++i_r) {
    for (int i_mu_s = 0; i_mu_s < table.width; ++i_mu_s) {
      const RMu rm = irradianceTexelConfig(ctx.sampler.domain(), table.width, table.height, i_mu_s, i_r);
      // Mean cosine of the sun disk's directions on a horizontal surface,
      // counting only the part above the surface's horizon (small-disk
      // approximation): mu_s when the whole disk is up, 0 when it is all down.
      double mean_cosine;
      if (rm.mu < -alpha) {
        mean_cosine = 0.0;
      } else if (rm.mu > alpha) {
        mean_cosine = rm.mu;
      } else {
        mean_cosine = (rm.mu + alpha) * (rm.mu + alpha) / (4.0 * alpha);
      }
      table.at(i_mu_s, i_r) = ctx.atmosphere.sun_irradiance *
                              glm::exp(-ctx.sampler.opticalDepthToTop(optical_depth, rm.r, rm.mu)) *
                              static_cast<float>(mean_cosine);
    }
    ctx.progress.advance(1);
  }
  return table;
}

}  // namespace skybake
