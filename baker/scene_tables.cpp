#include "baker/scene_tables.h"

namespace skybake {
namespace {

// The density at the scene's density texels (mu linear, nu clamped to what
// each texel's mu and mu_s allow), interpolated in the whole domain's table.
// Both tables are divided by the same shape, which depends on r and nu only.
Texture4D interpolateDensity(const TableSampler& scene, const TableSampler& whole, const Texture4D& density) {
  const AtmosphereDomain& d = scene.domain();
  const ScatteringSizes& s = scene.scatteringSizes();
  Texture4D out(s.r, s.mu, s.mu_s, s.nu);
#pragma omp parallel for collapse(2) schedule(static)
  for (int i_r = 0; i_r < s.r; ++i_r) {
    for (int i_mu = 0; i_mu < s.mu; ++i_mu) {
      const double r = rFromScatteringTexel(d, s, i_r);
      const double mu = muFromDensityTexel(i_mu, s.mu);
      for (int i_mu_s = 0; i_mu_s < s.mu_s; ++i_mu_s) {
        const double mu_s = muSFromScatteringTexel(d, s, i_mu_s);
        for (int i_nu = 0; i_nu < s.nu; ++i_nu) {
          const double nu = clampNu(nuOfScatteringSlice(i_nu, s.nu), mu, mu_s);
          out.at(i_r, i_mu, i_mu_s, i_nu) = whole.multipleDensity(density, r, mu, mu_s, nu);
        }
      }
    }
  }
  return out;
}

}  // namespace

void narrowTablesToScene(const StageContext& scene, const TableSampler& whole, const Texture2D& optical_depth,
                         const MultipleScatteringPhase& stored_shape, BakeTables& tables) {
  computeSingleScatteringTables(scene, optical_depth, tables.single_rayleigh, tables.single_mie);
  tables.multiple_scattering =
      computeMultipleScatteringTable(scene, optical_depth, whole, tables.multiple_density, stored_shape);
  tables.multiple_density = interpolateDensity(scene.sampler, whole, tables.multiple_density);
}

}  // namespace skybake
