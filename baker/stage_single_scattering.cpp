#include <omp.h>

#include "baker/local_frame.h"
#include "runtime/atmosphere_media.h"
#include "runtime/planet_shadow.h"
#include "runtime/ray_quadrature.h"
#include "baker/stages.h"

namespace skybake {
namespace {

// 16 sub-intervals x 4 Gauss nodes per sunlit or shadowed piece of the ray
// (more where a sub-interval is optically thick, see ray_quadrature.h): a
// vertical ray through Earth's 60 km holds 50 Mie scale heights, 3.1 per
// sub-interval, where the 4-point rule is accurate to ~1e-4 (a 50-step
// trapezoid is 8 % high on the same ray).
constexpr int kSingleScatteringSegments = 16;

}  // namespace

SingleScattering computeSingleScattering(const StageContext& ctx, const Texture2D& optical_depth,
                                         double r, double mu, double mu_s, double nu,
                                         bool ray_intersects_ground) {
  const AtmosphereParameters& a = ctx.atmosphere;
  const AtmosphereMedia media(a);
  const TableSampler& sampler = ctx.sampler;
  const double length = ray_intersects_ground ? distanceToInnerSphere(r, mu, a.bottom_radius_m)
                                              : distanceToOuterSphere(r, mu, a.top_radius_m);
  Spectrum rayleigh(0.0f);
  Spectrum mie(0.0f);
  auto addNode = [&](double t, double w) {
    const double r_t = std::clamp(radiusAlongRay(r, mu, t), a.bottom_radius_m, a.top_radius_m);
    const double mu_s_t = clampCosine((r * mu_s + t * nu) / r_t);
    const Spectrum transmittance =
        glm::exp(-sampler.opticalDepthAlongRay(optical_depth, r, mu, t, ray_intersects_ground)) *
        sampler.transmittanceToSun(optical_depth, r_t, mu_s_t, a.sun_angular_radius_rad);
    const double altitude = r_t - a.bottom_radius_m;
    rayleigh += transmittance * static_cast<float>(w * media.rayleighDensity(altitude));
    mie += transmittance * static_cast<float>(w * media.mieDensity(altitude));
  };
  auto largestExtinctionAt = [&](double t) {
    return media.largestExtinction(std::clamp(radiusAlongRay(r, mu, t), a.bottom_radius_m, a.top_radius_m) -
                                   a.bottom_radius_m);
  };
  // Each piece between the shadow's edges gets its own rule, so none spans
  // the jump where the sun appears or disappears.
  const ShadowCrossings crossings = planetShadowCrossings(
      glm::dvec3(0.0, 0.0, r), directionFromZenithCosine(mu), sunDirectionInViewFrame(mu, mu_s, nu),
      a.bottom_radius_m, length);
  double piece_start = 0.0;
  for (int i = 0; i <= crossings.count; ++i) {
    const double piece_end = i < crossings.count ? crossings.distance[i] : length;
    forEachOpticallyThinNode(piece_start, piece_end, kSingleScatteringSegments, -r * mu, largestExtinctionAt, addNode);
    piece_start = piece_end;
  }
  return {rayleigh * a.sun_irradiance * a.rayleigh_scattering,
          mie * a.sun_irradiance * a.mie_scattering};
}

void computeSingleScatteringTables(const StageContext& ctx, const Texture2D& optical_depth,
                                   Texture4D& rayleigh, Texture4D& mie) {
  const ScatteringSizes& s = ctx.sampler.scatteringSizes();
  rayleigh = Texture4D(s.r, s.mu, s.mu_s, s.nu);
  mie = Texture4D(s.r, s.mu, s.mu_s, s.nu);
#pragma omp parallel for collapse(2) schedule(dynamic)
  for (int i_r = 0; i_r < s.r; ++i_r) {
    for (int i_mu = 0; i_mu < s.mu; ++i_mu) {
      for (int i_nu = 0; i_nu < s.nu; ++i_nu) {
        for (int i_mu_s = 0; i_mu_s < s.mu_s; ++i_mu_s) {
          const ScatteringTexelConfig c =
              scatteringTexelConfig(ctx.sampler.domain(), s, i_r, i_mu, i_mu_s, i_nu);
          const SingleScattering single = computeSingleScattering(
              ctx, optical_depth, c.r, c.mu, c.mu_s, c.nu, c.ray_intersects_ground);
          rayleigh.at(i_r, i_mu, i_mu_s, i_nu) = single.rayleigh;
          mie.at(i_r, i_mu, i_mu_s, i_nu) = single.mie;
        }
      }
      ctx.progress.advance(1);
    }
  }
}

}  // namespace skybake
