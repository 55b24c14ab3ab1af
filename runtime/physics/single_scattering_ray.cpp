#include "runtime/physics/single_scattering_ray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "data_formats/error.h"
#include "runtime/physics/atmosphere_media.h"
#include "runtime/physics/ray_quadrature.h"
#include "runtime/physics/sunless_segment.h"
#include "runtime/sky_lookup_constants.h"

namespace skybake {

double integratedSingleScatteringWeight(double mu_s) {
  const double x = std::clamp(1.0 - mu_s / kIntegratedSingleScatteringTopCosine, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

namespace {

// The sunlight at a node, seen from the ray's start: through the sun's
// path to the node and the view ray back (one exponential), times the part
// of the sun's disk that lights the node.
SpectrumD sunlightToStart(const Spectrum& sun_depth, const Spectrum& view_depth, double visible) {
  return SpectrumD(glm::exp(-(sun_depth + view_depth)) * static_cast<float>(visible));
}

}  // namespace

SingleScattering integrateSingleScattering(const TableSampler& sampler, const Texture2D& optical_depth,
                                           const AtmosphereParameters& a, const SunlitRay& ray, double t_start,
                                           double t_end, int segments, const MoonAlongRay* moon,
                                           const ColourWavelengths* colour) {
  // A light shaft's shadow can reach past the ray's end: nothing is lit.
  if (!(t_end > t_start)) return {Spectrum(0.0f), Spectrum(0.0f)};
  const AtmosphereMedia media(a);
  const double r = ray.r, mu = ray.mu;
  auto radiusAt = [&](double t) { return std::clamp(radiusAlongRay(r, mu, t), a.bottom_radius_m, a.top_radius_m); };
  // Per pass: the bake's own lanes, or each wavelength group's of a colour
  // bake, weighted into X, Y, Z once summed (the weights are the same at
  // every node).
  const size_t passes = colour == nullptr ? 1 : colour->optical_depth.size();
  if (passes > kMaxWavelengthGroups) throw Error(ErrorKind::Internal, "integrateSingleScattering: too many groups");
  std::array<SpectrumD, kMaxWavelengthGroups> rayleigh, mie;
  rayleigh.fill(SpectrumD(0.0));
  mie.fill(SpectrumD(0.0));
  // The view ray's depths from its start, per pass's table.
  std::array<std::optional<TableSampler::DepthAlongRay>, kMaxWavelengthGroups> view_depths;
  for (size_t g = 0; g < passes; ++g) {
    view_depths[g].emplace(sampler, colour == nullptr ? optical_depth : colour->optical_depth[g], r, mu,
                           ray.ray_intersects_ground);
  }
  auto node = [&](double t, double w) {
    const double r_t = radiusAt(t);
    const double mu_s_t = clampCosine((r * ray.mu_s + t * ray.nu) / r_t);
    // As TableSampler::transmittanceToSun, with one exponential for the
    // sunlight's whole path, to the node and on to the ray's start; whether
    // the node is lit first, before any table read.
    const double visible = TableSampler::SunDiskAtR(sampler, r_t, a.sun_angular_radius_rad).visibleFraction(mu_s_t) *
                           (moon ? moon->visibleSunFraction(t) : 1.0);
    if (visible <= 0.0) return;  // in the planet's shadow or the moon's umbra
    const TableSampler::OpticalDepthFromR at_node(sampler, r_t);
    const double sun_coord = at_node.muCoord(mu_s_t);
    const double altitude = r_t - a.bottom_radius_m;
    const double rayleigh_weight = w * media.rayleighDensity(altitude);
    const double mie_weight = w * media.mieDensity(altitude);
    for (size_t g = 0; g < passes; ++g) {
      const Texture2D& depths = colour == nullptr ? optical_depth : colour->optical_depth[g];
      const SpectrumD light =
          sunlightToStart(at_node.opticalDepth(depths, sun_coord), view_depths[g]->to(t, r_t, at_node), visible);
      rayleigh[g] += light * rayleigh_weight;
      mie[g] += light * mie_weight;
    }
  };
  // The rule's pieces come from the ray alone; the shadow's edges cut them.
  const ShadowCrossings crossings = planetShadowCrossings(r, mu, ray.mu_s, ray.nu, a.bottom_radius_m, t_end);
  const SunlessSegmentTest sunless(r, mu, ray.mu_s, ray.nu, sampler.domain().bottom_radius_m, a.sun_angular_radius_rad);
  forEachOpticallyThinNodeCutAt(
      t_start, t_end, segments, -r * mu, crossings.distance.data(), crossings.count,
      [&](double t) { return media.largestExtinction(radiusAt(t) - a.bottom_radius_m); },
      [&](double start, double end) { return sunless.sunless(start, end); }, node, media.largestExtinctionBound());
  if (colour == nullptr) {
    return {Spectrum(rayleigh[0]) * a.sun_irradiance * a.rayleigh_scattering,
            Spectrum(mie[0]) * a.sun_irradiance * a.mie_scattering};
  }
  SpectrumD rayleigh_xyz(0.0), mie_xyz(0.0);
  for (size_t g = 0; g < passes; ++g) {
    const WavelengthGroupToXyz& to_xyz = colour->to_xyz[g];
    for (int c = 0; c < kCieXyzChannels; ++c) {
      rayleigh_xyz[c] += glm::dot(to_xyz.rayleigh[c], rayleigh[g]);
      mie_xyz[c] += glm::dot(to_xyz.mie[c], mie[g]);
    }
  }
  return {Spectrum(rayleigh_xyz), Spectrum(mie_xyz)};
}

SingleScatteringAlongRay::SingleScatteringAlongRay(const TableSampler& sampler, const Texture2D& optical_depth,
                                                   const AtmosphereParameters& a, double r, double mu,
                                                   bool ray_intersects_ground, double t_start, double t_end,
                                                   int segments)
    : sampler_(sampler),
      optical_depth_(optical_depth),
      a_(a),
      r_(r),
      mu_(mu),
      t_end_(t_end),
      view_depth_(sampler, optical_depth, r, mu, ray_intersects_ground) {
  if (!(t_end > t_start)) return;
  const AtmosphereMedia media(a);
  forEachOpticallyThinPiece(
      t_start, t_end, segments, -r * mu,
      [&](double t) { return media.largestExtinction(radiusAt(t) - a.bottom_radius_m); },
      [&](double start, double end) {
        pieces_.push_back({start, end, nodes_.size()});
        forEachQuadratureNode(start, end, 1, [&](double t, double w) { nodes_.push_back(nodeAt(t, w)); });
      },
      media.largestExtinctionBound());
}

double SingleScatteringAlongRay::radiusAt(double t) const {
  return std::clamp(radiusAlongRay(r_, mu_, t), a_.bottom_radius_m, a_.top_radius_m);
}

SingleScatteringAlongRay::Node SingleScatteringAlongRay::nodeAt(double t, double w) const {
  const AtmosphereMedia media(a_);
  const double r_t = radiusAt(t);
  const double altitude = r_t - a_.bottom_radius_m;
  const TableSampler::SunFromR sun(sampler_, r_t, a_.sun_angular_radius_rad);
  return {t,  r_t, w * media.rayleighDensity(altitude), w * media.mieDensity(altitude), view_depth_.to(t, r_t, sun),
          sun};
}

SingleScattering SingleScatteringAlongRay::under(double mu_s, double nu) const {
  if (pieces_.empty()) return {Spectrum(0.0f), Spectrum(0.0f)};
  SpectrumD rayleigh(0.0), mie(0.0);
  // As integrateSingleScattering's node, from what the node holds.
  auto add = [&](const Node& n) {
    const double mu_s_t = clampCosine((r_ * mu_s + n.t * nu) / n.r_t);
    const double visible = n.sun.visibleFraction(mu_s_t);
    if (visible <= 0.0) return;
    const SpectrumD light =
        sunlightToStart(n.sun.opticalDepth(optical_depth_, n.sun.muCoord(mu_s_t)), n.view_depth, visible);
    rayleigh += light * n.rayleigh_weight;
    mie += light * n.mie_weight;
  };
  const ShadowCrossings crossings = planetShadowCrossings(r_, mu_, mu_s, nu, a_.bottom_radius_m, t_end_);
  const SunlessSegmentTest sunless(r_, mu_, mu_s, nu, sampler_.domain().bottom_radius_m, a_.sun_angular_radius_rad);
  for (const Piece& p : pieces_) {
    // As forEachOpticallyThinNodeCutAt: the piece cut where the shadow's
    // edges fall inside it, each part its own rule, the parts that see no
    // sun skipped; a whole piece's nodes are the stored ones.
    forEachPartCutAt(p.start, p.end, crossings.distance.data(), crossings.count, [&](double start, double end) {
      if (sunless.sunless(start, end)) return;
      if (start == p.start && end == p.end) {
        for (int k = 0; k < kGaussNodes; ++k) add(nodes_[p.first_node + k]);
      } else {
        forEachQuadratureNode(start, end, 1, [&](double t, double w) { add(nodeAt(t, w)); });
      }
    });
  }
  return {Spectrum(rayleigh) * a_.sun_irradiance * a_.rayleigh_scattering,
          Spectrum(mie) * a_.sun_irradiance * a_.mie_scattering};
}

}  // namespace skybake
