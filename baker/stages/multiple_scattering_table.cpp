#include <omp.h>

#include <algorithm>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "baker/numerics/log_cubic.h"
#include "baker/numerics/vector_exp.h"
#include "baker/stages/multiple_scattering_table.h"
#include "baker/stages/row_sun_texels.h"
#include "runtime/physics/atmosphere_media.h"
#include "runtime/physics/ray_quadrature.h"
#include "runtime/tables/table_sampler.h"

namespace skybake {
namespace {

// A quadrature node on a view ray and what along the ray does not depend on
// the sun: shared by every (mu_s, nu) texel of the ray's (r, mu).
struct RayNode {
  double t;
  double weight;
  double r;
  Spectrum transmittance;  // from the ray's start to the node
  SpectrumD peak_weight;   // of the multiple-scattering shape at the node's altitude
  AxisLerp density_r;      // where the node falls on the density table's r and mu axes
  AxisLerp density_mu;
};

void collectRayNodes(const StageContext& ctx, const Texture2D& optical_depth, const TableSampler& density_sampler,
                     const MultipleScatteringPhase& shape, const ScatteringTexelConfig& c, int ray_segments,
                     std::vector<RayNode>& nodes) {
  const AtmosphereParameters& a = ctx.atmosphere;
  const AtmosphereMedia media(a);
  const TableSampler& sampler = ctx.sampler;
  const double length = distanceToAtmosphereEnd(c.r, c.mu, a.bottom_radius_m, a.top_radius_m, c.ray_intersects_ground);
  auto radiusAt = [&](double t) { return std::clamp(radiusAlongRay(c.r, c.mu, t), a.bottom_radius_m, a.top_radius_m); };
  nodes.clear();
  forEachOpticallyThinNode(
      0.0, length, ray_segments, -c.r * c.mu,
      [&](double t) { return media.largestExtinction(radiusAt(t) - a.bottom_radius_m); },
      [&](double t, double w) {
        const double r_t = radiusAt(t);
        const double mu_t = cosineAlongRay(c.r, c.mu, t, r_t);
        // The density table's mu is linear (densityCoordMu); its other axes are the scattering tables'.
        const AtmosphereDomain& d = density_sampler.domain();
        const ScatteringSizes& s = density_sampler.scatteringSizes();
        const double u_r = scatteringCoordR(d, s.r, d.distanceToHorizon(r_t));
        nodes.push_back({t, w, r_t,
                         glm::exp(-sampler.opticalDepthAlongRay(optical_depth, c.r, c.mu, t, c.ray_intersects_ground)),
                         shape.peakWeightAt(r_t - a.bottom_radius_m), axisLerpFromTextureCoord(u_r, s.r),
                         axisLerpFromTextureCoord(densityCoordMu(mu_t, s.mu), s.mu)});
      },
      media.largestExtinctionBound());
}

// The density table at one node's (r, mu), interpolated there once: a
// nu x mu_s plane (in the table's own order, entry i_nu * rows + i_mu_s)
// that every sun texel of the ray then interpolates bilinearly (4 texels
// per lookup instead of 16). `rows` sun rows from the lowest sun up: the
// whole plane, or the rows that carry logarithms. Each nu's rows are
// contiguous in the table, so the blend runs over their floats in one loop
// that vectorizes (per channel the same arithmetic as a blend of Spectrums).
void interpolateAtNode(const Texture4D& density, const RayNode& n, int rows, std::vector<Spectrum>& plane) {
  plane.resize(static_cast<size_t>(rows) * density.nu_size);
  const AxisLerp& r = n.density_r;
  const AxisLerp& mu = n.density_mu;
  const float mu_w = mu.w1, r_w = r.w1;
  const int floats = rows * kMaxChannels;
  for (int i_nu = 0; i_nu < density.nu_size; ++i_nu) {
    auto row = [&](int i_r, int i_mu) { return glm::value_ptr(density.at(i_r, i_mu, 0, i_nu)); };
    const float* lower_r_lower_mu = row(r.i0, mu.i0);
    const float* lower_r_upper_mu = row(r.i0, mu.i1);
    const float* upper_r_lower_mu = row(r.i1, mu.i0);
    const float* upper_r_upper_mu = row(r.i1, mu.i1);
    float* out = glm::value_ptr(plane[static_cast<size_t>(i_nu) * rows]);
#pragma omp simd
    for (int j = 0; j < floats; ++j) {
      const float r0 = lower_r_lower_mu[j] + (lower_r_upper_mu[j] - lower_r_lower_mu[j]) * mu_w;
      const float r1 = upper_r_lower_mu[j] + (upper_r_upper_mu[j] - upper_r_lower_mu[j]) * mu_w;
      out[j] = r0 + (r1 - r0) * r_w;
    }
  }
}

// The plane at a sun (mu_s) and nu: linear across nu, across mu_s linear
// or, for a sun below the horizon, a cubic in the logarithm
// (baker/numerics/log_cubic.h). `log_plane` holds the rows the cubic reads
// (log_rows of them, rows_with_logs), interpolated at the node from the
// density's logarithms (so geometrically across r and mu, which the density
// falls along exponentially too).
Spectrum samplePlane(const std::vector<Spectrum>& plane, const std::vector<Spectrum>& log_plane, int nu_size,
                     int log_rows, const AxisLerp& mu_s, const AxisLerp& nu, bool log_cubic) {
  const int rows = static_cast<int>(plane.size()) / nu_size;
  auto at = [](const std::vector<Spectrum>& p, int p_rows, int i_mu_s, int i_nu) -> const Spectrum& {
    return p[static_cast<size_t>(i_nu) * p_rows + i_mu_s];
  };
  auto along_nu = [&](const std::vector<Spectrum>& p, int p_rows, int i_mu_s) {
    const Spectrum& a = at(p, p_rows, i_mu_s, nu.i0);
    const Spectrum& b = at(p, p_rows, i_mu_s, nu.i1);
    return a + (b - a) * nu.w1;
  };
  if (!log_cubic) {
    const Spectrum a =
        at(plane, rows, mu_s.i0, nu.i0) + (at(plane, rows, mu_s.i1, nu.i0) - at(plane, rows, mu_s.i0, nu.i0)) * mu_s.w1;
    const Spectrum b =
        at(plane, rows, mu_s.i0, nu.i1) + (at(plane, rows, mu_s.i1, nu.i1) - at(plane, rows, mu_s.i0, nu.i1)) * mu_s.w1;
    return a + (b - a) * nu.w1;
  }
  const int i_before = std::max(mu_s.i0 - 1, 0), i_after = std::min(mu_s.i1 + 1, rows - 1);
  const Spectrum lower = along_nu(plane, rows, mu_s.i0), upper = along_nu(plane, rows, mu_s.i1);
  const Spectrum log_before = along_nu(log_plane, log_rows, i_before),
                 log_lower = along_nu(log_plane, log_rows, mu_s.i0), log_upper = along_nu(log_plane, log_rows, mu_s.i1),
                 log_after = along_nu(log_plane, log_rows, i_after);
  return blendLogCubic(
      {lower, upper, log_before, log_lower, log_upper, log_after, i_before == mu_s.i0, i_after == mu_s.i1}, mu_s.w1);
}

// How many of the density's sun rows (from the lowest sun up) a cubic for a
// sun below the horizon reads: those below the horizon, the first above it and
// the one after (the texel beyond the interval).
int rowsWithLogs(const std::vector<double>& density_texel_mu_s) {
  int below = 0;
  while (below < static_cast<int>(density_texel_mu_s.size()) && density_texel_mu_s[below] < 0.0) ++below;
  // A lerp clamped to the lowest texels reads rows 0 to 2 even with none below.
  return std::min(std::max(below, 1) + 2, static_cast<int>(density_texel_mu_s.size()));
}

}  // namespace

Texture4D computeMultipleScatteringTable(const StageContext& ctx, const Texture2D& optical_depth,
                                         const TableSampler& density_sampler, const Texture4D& density,
                                         const MultipleScatteringPhase& shape, int ray_segments) {
  const TableSampler& sampler = ctx.sampler;
  const ScatteringSizes& s = sampler.scatteringSizes();
  const ScatteringSizes& density_sizes = density_sampler.scatteringSizes();
  const ScatteringMuSCoordMap density_mu_s_coord =
      ScatteringMuSCoordMap::of(density_sampler.domain(), density_sizes.mu_s);
  const std::vector<double> texel_mu_s = scatteringTexelMuS(sampler.domain(), s);
  const int rows_with_logs = rowsWithLogs(scatteringTexelMuS(density_sampler.domain(), density_sizes));
  // The logarithm of every texel once, rather than of each node's plane
  // (as many logarithms per node as the plane's lookups).
  Texture4D log_density(density.r_size, density.mu_size, density.mu_s_size, density.nu_size);
  logOfSpectra(density.texels.data(), log_density.texels.data(), density.texels.size());
  constexpr double kBroad = MultipleScatteringPhase::kBroad;
  Texture4D table(s.r, s.mu, s.mu_s, s.nu);
#pragma omp parallel
  {
    std::vector<RayNode> nodes;
    std::vector<std::vector<Spectrum>> planes;      // one per node
    std::vector<std::vector<Spectrum>> log_planes;  // their logarithms, the rows_with_logs lowest sun rows
    RowSunTexels suns;
    std::vector<AxisLerp> density_nu;   // per sun: nu is constant along a straight ray, so is its interpolation
    std::vector<double> mu_s_at_node;   // per sun: its cosine at the current node
    std::vector<double> mu_s_position;  // per sun: its coordinate on the density table at the current node
    // Per sun, the density integrated along the ray times the broad and the
    // peaked part of the shape at each node: the shape at the node is
    // kBroad + w (peak - kBroad), so the integral with it is
    // kBroad * broad + (peak - kBroad) * peaked.
    std::vector<Spectrum> broad, peaked;
#pragma omp for collapse(2) schedule(dynamic)
    for (int i_r = 0; i_r < s.r; ++i_r) {
      for (int i_mu = 0; i_mu < s.mu; ++i_mu) {
        const ScatteringTexelConfig row = scatteringTexelConfig(sampler.domain(), s, i_r, i_mu, 0, 0);
        collectRayNodes(ctx, optical_depth, density_sampler, shape, row, ray_segments, nodes);
        if (planes.size() < nodes.size()) planes.resize(nodes.size());
        if (log_planes.size() < nodes.size()) log_planes.resize(nodes.size());
        for (size_t k = 0; k < nodes.size(); ++k) {
          interpolateAtNode(density, nodes[k], density.mu_s_size, planes[k]);
          interpolateAtNode(log_density, nodes[k], rows_with_logs, log_planes[k]);
        }
        suns.collect(s, texel_mu_s, row.mu);
        const size_t count = suns.size();
        density_nu.resize(count);
        for (size_t i = 0; i < count; ++i) density_nu[i] = axisLerpNu((suns.nu[i] + 1.0) * 0.5, density_sizes.nu);
        broad.assign(count, Spectrum(0.0f));
        peaked.assign(count, Spectrum(0.0f));
        mu_s_at_node.resize(count);
        mu_s_position.resize(count);
        const double* sun_mu_s = suns.mu_s.data();
        const double* sun_nu = suns.nu.data();
        for (size_t k = 0; k < nodes.size(); ++k) {
          const RayNode& n = nodes[k];
          const Spectrum light = n.transmittance * static_cast<float>(n.weight);
          const Spectrum light_peaked = light * Spectrum(n.peak_weight);
          const std::vector<Spectrum>& plane = planes[k];
          // The sun's coordinate at the node for every sun first: a loop
          // without table reads, which vectorizes.
#pragma omp simd
          for (size_t i = 0; i < count; ++i) {
            mu_s_at_node[i] = clampCosine((row.r * sun_mu_s[i] + n.t * sun_nu[i]) / n.r);
            mu_s_position[i] = density_mu_s_coord(mu_s_at_node[i]);
          }
          for (size_t i = 0; i < count; ++i) {
            const AxisLerp mu_s_lerp = axisLerpFromTextureCoord(mu_s_position[i], density_sizes.mu_s);
            const Spectrum value = samplePlane(plane, log_planes[k], density_sizes.nu, rows_with_logs, mu_s_lerp,
                                               density_nu[i], mu_s_at_node[i] < 0.0);
            broad[i] += value * light;
            peaked[i] += value * light_peaked;
          }
        }
        // The density is stored divided by the shape at its texels: the
        // shape at each node gave it back, the shape at this texel divides
        // the result for storage.
        const SpectrumD texel_peak_weight = shape.peakWeightAt(row.r - ctx.atmosphere.bottom_radius_m);
        for (size_t i = 0; i < count; ++i) {
          const double peak = shape.peakAt(suns.nu[i]);
          const Spectrum value =
              (broad[i] * static_cast<float>(kBroad) + peaked[i] * static_cast<float>(peak - kBroad)) /
              MultipleScatteringPhase::withPeak(texel_peak_weight, peak);
          const RowSunTexels::Slices& slices = suns.slices[i];
          for (int i_nu = slices.first_nu; i_nu <= slices.last_nu; ++i_nu) {
            table.at(i_r, i_mu, slices.i_mu_s, i_nu) = value;
          }
        }
        ctx.progress.advance(1);
      }
    }
  }
  return table;
}

}  // namespace skybake
