#include <omp.h>

#include <optional>
#include <vector>

#include "baker/numerics/vector_exp.h"
#include "baker/stages/row_sun_texels.h"
#include "baker/stages/single_scattering_tables.h"
#include "runtime/physics/atmosphere_media.h"
#include "runtime/physics/planet_shadow.h"
#include "runtime/physics/ray_quadrature.h"
#include "runtime/physics/single_scattering_ray.h"

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

// Appends the nodes of [0, length] of the ray (r, mu), in `segments`
// sub-intervals (forEachOpticallyThinNode: as integrateSingleScattering
// places them where the planet's shadow does not cross the ray).
void collectViewNodes(const StageContext& ctx, const Texture2D& optical_depth, double r, double mu,
                      bool ray_intersects_ground, double length, int segments, std::vector<ViewNode>& nodes) {
  const AtmosphereParameters& a = ctx.atmosphere;
  const AtmosphereMedia media(a);
  auto radiusAt = [&](double t) { return std::clamp(radiusAlongRay(r, mu, t), a.bottom_radius_m, a.top_radius_m); };
  forEachOpticallyThinNode(
      0.0, length, segments, -r * mu,
      [&](double t) { return media.largestExtinction(radiusAt(t) - a.bottom_radius_m); },
      [&](double t, double w) {
        const double r_t = radiusAt(t);
        const double altitude = r_t - a.bottom_radius_m;
        nodes.push_back({t, r_t,
                         glm::exp(-ctx.sampler.opticalDepthAlongRay(optical_depth, r, mu, t, ray_intersects_ground)),
                         w * media.rayleighDensity(altitude), w * media.mieDensity(altitude)});
      },
      media.largestExtinctionBound());
}

// The suns of one view ray that share its nodes: their cosines in arrays the
// node loop vectorizes over, and the single scattering they accumulate.
struct SunBatch {
  std::vector<double> mu_s, nu;
  std::vector<double> mu_coord, visible;  // at the current node
  std::vector<Spectrum> rayleigh, mie;
  void clear() {
    mu_s.clear();
    nu.clear();
  }
  void add(double sun_mu_s, double sun_nu) {
    mu_s.push_back(sun_mu_s);
    nu.push_back(sun_nu);
  }
};

// Single scattering from the nodes of one view ray from r for every sun of
// the batch: per node, first where each sun falls on the transmittance
// table and how much of its disk is up (a loop without table reads, which
// vectorizes), then the reads and the sums.
void sumOverNodes(const StageContext& ctx, const Texture2D& optical_depth, const std::vector<ViewNode>& nodes, double r,
                  SunBatch& suns) {
  const AtmosphereParameters& a = ctx.atmosphere;
  const size_t count = suns.mu_s.size();
  suns.rayleigh.assign(count, Spectrum(0.0f));
  suns.mie.assign(count, Spectrum(0.0f));
  suns.mu_coord.resize(count);
  suns.visible.resize(count);
  const double* sun_mu_s = suns.mu_s.data();
  const double* sun_nu = suns.nu.data();
  double* mu_coord = suns.mu_coord.data();
  double* visible = suns.visible.data();
  for (const ViewNode& n : nodes) {
    const TableSampler::SunFromR sun(ctx.sampler, n.r_t, a.sun_angular_radius_rad);
    const double t = n.t, r_t = n.r_t;  // locals: GCC does not vectorize the loop reading them through n
#pragma omp simd
    for (size_t i = 0; i < count; ++i) {
      const double mu_s_t = clampCosine((r * sun_mu_s[i] + t * sun_nu[i]) / r_t);
      mu_coord[i] = sun.muCoord(mu_s_t);
      visible[i] = sun.visibleFraction(mu_s_t);
    }
    const Spectrum rayleigh_light = n.view_transmittance * static_cast<float>(n.rayleigh_weight);
    const Spectrum mie_light = n.view_transmittance * static_cast<float>(n.mie_weight);
    for (size_t i = 0; i < count; ++i) {
      if (visible[i] <= 0.0) continue;
      const Spectrum to_sun =
          expOfNegated(sun.opticalDepth(optical_depth, mu_coord[i])) * static_cast<float>(visible[i]);
      suns.rayleigh[i] += to_sun * rayleigh_light;
      suns.mie[i] += to_sun * mie_light;
    }
  }
  for (size_t i = 0; i < count; ++i) {
    suns.rayleigh[i] *= a.sun_irradiance * a.rayleigh_scattering;
    suns.mie[i] *= a.sun_irradiance * a.mie_scattering;
  }
}

}  // namespace

SingleScattering computeSingleScattering(const StageContext& ctx, const Texture2D& optical_depth, double r, double mu,
                                         double mu_s, double nu, bool ray_intersects_ground) {
  const AtmosphereParameters& a = ctx.atmosphere;
  const double length = distanceToAtmosphereEnd(r, mu, a.bottom_radius_m, a.top_radius_m, ray_intersects_ground);
  return integrateSingleScattering(ctx.sampler, optical_depth, a, {r, mu, mu_s, nu, ray_intersects_ground}, 0.0, length,
                                   kSingleScatteringSegments);
}

void computeSingleScatteringTables(const StageContext& ctx, const Texture2D& optical_depth, Texture4D& rayleigh,
                                   Texture4D& mie) {
  const ScatteringSizes& s = ctx.sampler.scatteringSizes();
  rayleigh = Texture4D(s.r, s.mu, s.mu_s, s.nu);
  mie = Texture4D(s.r, s.mu, s.mu_s, s.nu);
  const std::vector<double> texel_mu_s = scatteringTexelMuS(ctx.sampler.domain(), s);
#pragma omp parallel
  {
    std::vector<ViewNode> whole_ray;
    RowSunTexels suns;
    SunBatch shared;
    std::vector<size_t> shared_suns;  // which of the row's suns the shared batch holds
#pragma omp for collapse(2) schedule(dynamic)
    for (int i_r = 0; i_r < s.r; ++i_r) {
      for (int i_mu = 0; i_mu < s.mu; ++i_mu) {
        // The row's ray and its nodes, for every sun the shadow leaves alone.
        const ScatteringTexelConfig row = scatteringTexelConfig(ctx.sampler.domain(), s, i_r, i_mu, 0, 0);
        const double length = distanceToAtmosphereEnd(row.r, row.mu, ctx.atmosphere.bottom_radius_m,
                                                      ctx.atmosphere.top_radius_m, row.ray_intersects_ground);
        whole_ray.clear();
        collectViewNodes(ctx, optical_depth, row.r, row.mu, row.ray_intersects_ground, length,
                         kSingleScatteringSegments, whole_ray);
        auto store = [&](size_t sun, const Spectrum& rayleigh_value, const Spectrum& mie_value) {
          const RowSunTexels::Slices& slices = suns.slices[sun];
          for (int i_nu = slices.first_nu; i_nu <= slices.last_nu; ++i_nu) {
            rayleigh.at(i_r, i_mu, slices.i_mu_s, i_nu) = rayleigh_value;
            mie.at(i_r, i_mu, slices.i_mu_s, i_nu) = mie_value;
          }
        };
        suns.collect(s, texel_mu_s, row.mu);
        shared.clear();
        shared_suns.clear();
        // The suns whose shadow crosses the ray: the ray integral itself,
        // which recomputes only the pieces the shadow's edges cut.
        std::optional<SingleScatteringAlongRay> cut_by_shadow;
        for (size_t i = 0; i < suns.size(); ++i) {
          const ShadowCrossings crossings =
              planetShadowCrossings(row.r, row.mu, suns.mu_s[i], suns.nu[i], ctx.atmosphere.bottom_radius_m, length);
          if (crossings.count == 0) {
            shared.add(suns.mu_s[i], suns.nu[i]);
            shared_suns.push_back(i);
            continue;
          }
          if (!cut_by_shadow) {
            cut_by_shadow.emplace(ctx.sampler, optical_depth, ctx.atmosphere, row.r, row.mu, row.ray_intersects_ground,
                                  0.0, length, kSingleScatteringSegments);
          }
          const SingleScattering value = cut_by_shadow->under(suns.mu_s[i], suns.nu[i]);
          store(i, value.rayleigh, value.mie);
        }
        sumOverNodes(ctx, optical_depth, whole_ray, row.r, shared);
        for (size_t j = 0; j < shared_suns.size(); ++j) store(shared_suns[j], shared.rayleigh[j], shared.mie[j]);
        ctx.progress.advance(1);
      }
    }
  }
}

}  // namespace skybake
