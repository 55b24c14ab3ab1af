#include <omp.h>

#include <vector>

#include "baker/local_frame.h"
#include "runtime/atmosphere_media.h"
#include "runtime/planet_shadow.h"
#include "runtime/ray_quadrature.h"
#include "baker/stages.h"

namespace skybake {
namespace {

// 8 sub-intervals x 4 Gauss nodes over the whole ray (more where a
// sub-interval is optically thick, see ray_quadrature.h): a vertical ray
// through Earth's 60 km holds 50 Mie scale heights, 6.2 per sub-interval,
// where the 4-point rule is 4e-4 low on the exponential (16 sub-intervals:
// 4e-6; no validated figure moved by more than 0.02 point between the two).
// A 50-step trapezoid is 8 % high on the same ray.
constexpr int kSingleScatteringSegments = 8;

// What a quadrature node of a view ray carries that does not depend on the
// sun: its position, the transmittance back to the ray's start and the
// weighted densities. Shared by every sun texel of an (r, mu) row whose ray
// the planet's shadow does not cross.
struct ViewNode {
  double t;
  double r_t;
  Spectrum view_transmittance;
  double rayleigh_weight;  // quadrature weight times Rayleigh density
  double mie_weight;
};

// Appends the nodes of [piece_start, piece_end] of the ray (r, mu), in
// `segments` sub-intervals.
void collectViewNodes(const StageContext& ctx, const Texture2D& optical_depth, double r, double mu,
                      bool ray_intersects_ground, double piece_start, double piece_end, int segments,
                      std::vector<ViewNode>& nodes) {
  const AtmosphereParameters& a = ctx.atmosphere;
  const AtmosphereMedia media(a);
  auto radiusAt = [&](double t) { return std::clamp(radiusAlongRay(r, mu, t), a.bottom_radius_m, a.top_radius_m); };
  forEachOpticallyThinNode(
      piece_start, piece_end, segments, -r * mu,
      [&](double t) { return media.largestExtinction(radiusAt(t) - a.bottom_radius_m); },
      [&](double t, double w) {
        const double r_t = radiusAt(t);
        const double altitude = r_t - a.bottom_radius_m;
        nodes.push_back({t, r_t,
                         glm::exp(-ctx.sampler.opticalDepthAlongRay(optical_depth, r, mu, t, ray_intersects_ground)),
                         w * media.rayleighDensity(altitude), w * media.mieDensity(altitude)});
      });
}

// Single scattering from the nodes of one view ray, the sun at (mu_s, nu).
SingleScattering sumOverNodes(const StageContext& ctx, const Texture2D& optical_depth,
                              const std::vector<ViewNode>& nodes, double r, double mu_s, double nu) {
  const AtmosphereParameters& a = ctx.atmosphere;
  Spectrum rayleigh(0.0f);
  Spectrum mie(0.0f);
  for (const ViewNode& n : nodes) {
    const double mu_s_t = clampCosine((r * mu_s + n.t * nu) / n.r_t);
    const Spectrum transmittance =
        n.view_transmittance * ctx.sampler.transmittanceToSun(optical_depth, n.r_t, mu_s_t, a.sun_angular_radius_rad);
    rayleigh += transmittance * static_cast<float>(n.rayleigh_weight);
    mie += transmittance * static_cast<float>(n.mie_weight);
  }
  return {rayleigh * a.sun_irradiance * a.rayleigh_scattering, mie * a.sun_irradiance * a.mie_scattering};
}

// Where the planet's shadow cuts the ray (r, mu) with the sun at (mu_s, nu).
ShadowCrossings shadowCrossings(const AtmosphereParameters& a, double r, double mu, double mu_s, double nu,
                                double length) {
  return planetShadowCrossings(glm::dvec3(0.0, 0.0, r), directionFromZenithCosine(mu),
                               sunDirectionInViewFrame(mu, mu_s, nu), a.bottom_radius_m, length);
}

// The nodes of the ray, each piece between the shadow's edges with its own
// rule, so none spans the jump where the sun appears or disappears.
void collectPiecewiseNodes(const StageContext& ctx, const Texture2D& optical_depth, double r, double mu,
                           bool ray_intersects_ground, const ShadowCrossings& crossings, double length,
                           std::vector<ViewNode>& nodes) {
  nodes.clear();
  double piece_start = 0.0;
  for (int i = 0; i <= crossings.count; ++i) {
    const double piece_end = i < crossings.count ? crossings.distance[i] : length;
    // Sub-intervals no longer than the whole ray's: as accurate, and a
    // ray cut in pieces costs a few nodes more than a whole one, not a
    // whole rule per piece.
    const double share = length > 0.0 ? (piece_end - piece_start) / length : 1.0;
    const int segments = std::clamp(static_cast<int>(std::ceil(kSingleScatteringSegments * share)), 1,
                                    kSingleScatteringSegments);
    collectViewNodes(ctx, optical_depth, r, mu, ray_intersects_ground, piece_start, piece_end, segments, nodes);
    piece_start = piece_end;
  }
}

}  // namespace

SingleScattering computeSingleScattering(const StageContext& ctx, const Texture2D& optical_depth,
                                         double r, double mu, double mu_s, double nu,
                                         bool ray_intersects_ground) {
  const AtmosphereParameters& a = ctx.atmosphere;
  const double length = distanceToAtmosphereEnd(r, mu, a.bottom_radius_m, a.top_radius_m, ray_intersects_ground);
  std::vector<ViewNode> nodes;
  collectPiecewiseNodes(ctx, optical_depth, r, mu, ray_intersects_ground,
                        shadowCrossings(ctx.atmosphere, r, mu, mu_s, nu, length), length, nodes);
  return sumOverNodes(ctx, optical_depth, nodes, r, mu_s, nu);
}

void computeSingleScatteringTables(const StageContext& ctx, const Texture2D& optical_depth,
                                   Texture4D& rayleigh, Texture4D& mie) {
  const ScatteringSizes& s = ctx.sampler.scatteringSizes();
  rayleigh = Texture4D(s.r, s.mu, s.mu_s, s.nu);
  mie = Texture4D(s.r, s.mu, s.mu_s, s.nu);
#pragma omp parallel
  {
    std::vector<ViewNode> whole_ray, pieces;
#pragma omp for collapse(2) schedule(dynamic)
    for (int i_r = 0; i_r < s.r; ++i_r) {
      for (int i_mu = 0; i_mu < s.mu; ++i_mu) {
        // The row's ray and its nodes, for every sun the shadow leaves alone.
        const ScatteringTexelConfig row = scatteringTexelConfig(ctx.sampler.domain(), s, i_r, i_mu, 0, 0);
        const double length = distanceToAtmosphereEnd(row.r, row.mu, ctx.atmosphere.bottom_radius_m,
                                                      ctx.atmosphere.top_radius_m, row.ray_intersects_ground);
        whole_ray.clear();
        collectViewNodes(ctx, optical_depth, row.r, row.mu, row.ray_intersects_ground, 0.0, length,
                         kSingleScatteringSegments, whole_ray);
        for (int i_mu_s = 0; i_mu_s < s.mu_s; ++i_mu_s) {
          // Slices clamped to the same end of the nu range are the same
          // texel: integrated once.
          double last_nu = 2.0;  // no nu
          for (int i_nu = 0; i_nu < s.nu; ++i_nu) {
            const ScatteringTexelConfig c =
                scatteringTexelConfig(ctx.sampler.domain(), s, i_r, i_mu, i_mu_s, i_nu);
            if (c.nu == last_nu) {
              rayleigh.at(i_r, i_mu, i_mu_s, i_nu) = rayleigh.at(i_r, i_mu, i_mu_s, i_nu - 1);
              mie.at(i_r, i_mu, i_mu_s, i_nu) = mie.at(i_r, i_mu, i_mu_s, i_nu - 1);
              continue;
            }
            last_nu = c.nu;
            const ShadowCrossings crossings = shadowCrossings(ctx.atmosphere, c.r, c.mu, c.mu_s, c.nu, length);
            const std::vector<ViewNode>* nodes = &whole_ray;
            if (crossings.count > 0) {
              collectPiecewiseNodes(ctx, optical_depth, c.r, c.mu, c.ray_intersects_ground, crossings, length,
                                    pieces);
              nodes = &pieces;
            }
            const SingleScattering single = sumOverNodes(ctx, optical_depth, *nodes, c.r, c.mu_s, c.nu);
            rayleigh.at(i_r, i_mu, i_mu_s, i_nu) = single.rayleigh;
            mie.at(i_r, i_mu, i_mu_s, i_nu) = single.mie;
          }
        }
        ctx.progress.advance(1);
      }
    }
  }
}

}  // namespace skybake
