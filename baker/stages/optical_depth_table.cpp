#include <omp.h>

#include "baker/numerics/optical_depth_integral.h"
#include "baker/stages/optical_depth_table.h"

namespace skybake {

Texture2D computeOpticalDepthTable(const StageContext& ctx) {
  const TextureSizes& s = ctx.sampler.sizes();
  Texture2D table(s.transmittance_mu, s.transmittance_r);
  const AtmosphereMedia media(ctx.atmosphere);
#pragma omp parallel for schedule(dynamic)
  for (int i_r = 0; i_r < table.height; ++i_r) {
    for (int i_mu = 0; i_mu < table.width; ++i_mu) {
      const RMu rm = transmittanceTexelConfig(ctx.sampler.domain(), table.width, table.height, i_mu, i_r);
      table.at(i_mu, i_r) = Spectrum(integrateOpticalDepthToTop(media, rm.r, rm.mu));
    }
    ctx.progress.advance(1);
  }
  return table;
}

}  // namespace skybake
