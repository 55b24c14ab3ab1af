#include <omp.h>

#include "runtime/ray_quadrature.h"
#include "baker/stages.h"

namespace skybake {
namespace {

// Same ray rule as single scattering: the density falls off with the
// constituents' scale heights, like the single-scattering integrand.
constexpr int kMultipleScatteringSegments = 16;

}  // namespace

Texture4D computeMultipleScatteringTable(const StageContext& ctx, const Texture2D& optical_depth,
                                         const Texture4D& density) {
  const AtmosphereParameters& a = ctx.atmosphere;
  const TableSampler& sampler = ctx.sampler;
  const ScatteringSizes& s = sampler.scatteringSizes();
  Texture4D table(s.r, s.mu, s.mu_s, s.nu);
#pragma omp parallel for collapse(2) schedule(dynamic)
  for (int i_r = 0; i_r < s.r; ++i_r) {
    for (int i_mu = 0; i_mu < s.mu; ++i_mu) {
      for (int i_nu = 0; i_nu < s.nu; ++i_nu) {
        for (int i_mu_s = 0; i_mu_s < s.mu_s; ++i_mu_s) {
          const ScatteringTexelConfig c = scatteringTexelConfig(sampler.domain(), s, i_r, i_mu, i_mu_s, i_nu);
          const double length = c.ray_intersects_ground
                                    ? distanceToInnerSphere(c.r, c.mu, a.bottom_radius_m)
                                    : distanceToOuterSphere(c.r, c.mu, a.top_radius_m);
          // nu is constant along a straight ray: its interpolation is too.
          const AxisLerp nu_lerp = axisLerpNu((c.nu + 1.0) * 0.5, s.nu);
          Spectrum sum(0.0f);
          forEachQuadratureNode(0.0, length, kMultipleScatteringSegments, [&](double t, double w) {
            const double r_t = std::clamp(radiusAlongRay(c.r, c.mu, t), a.bottom_radius_m, a.top_radius_m);
            const double mu_t = cosineAlongRay(c.r, c.mu, t, r_t);
            const double mu_s_t = clampCosine((c.r * c.mu_s + t * c.nu) / r_t);
            const Spectrum transmittance = glm::exp(
                -sampler.opticalDepthAlongRay(optical_depth, c.r, c.mu, t, c.ray_intersects_ground));
            const ScatteringCoord coord =
                sampler.scatteringCoord(r_t, mu_t, mu_s_t, c.nu, c.ray_intersects_ground);
            sum += sample4D(density, coord, nu_lerp) * transmittance * static_cast<float>(w);
          });
          table.at(i_r, i_mu, i_mu_s, i_nu) = sum;
        }
      }
      ctx.progress.advance(1);
    }
  }
  return table;
}

}  // namespace skybake
