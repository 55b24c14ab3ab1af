#include "baker/stages/scattering_density_kernel.h"

#include <omp.h>

#include <array>
#include <cmath>

#include "baker/numerics/gauss_legendre.h"
#include "runtime/physics/phase_functions.h"

namespace skybake {
namespace {

// Azimuths at which each phase function is sampled for its Fourier modes:
// 4 per mode kept, so modes up to kAzimuthModes alias only with modes above
// 3 kAzimuthModes (Earth's Mie peak: 0.8^96 ~ 5e-10 of the mean).
constexpr int kPhaseTransformAzimuths = 4 * kAzimuthModes;

// Gauss-Legendre nodes in theta on the sky side [0, horizon] and on the
// ground side [horizon, pi], each side split into the band next to the
// horizon (kDensityHorizonBand_rad wide, at most half the side) and the
// rest. The incident radiance jumps at the horizon (sky to lit ground) and
// peaks on both sides of it, where paths through the air are longest; a
// grid that straddles the horizon smears that peak, and in twilight, when
// the light reaching a point comes mostly from the horizon toward the sun,
// it is the largest error a uniform grid leaves (docs/MEASUREMENTS.md,
// "Scattering density"). Deep in twilight that light arrives within a
// degree or two of the horizon, hence the band's own nodes.
std::vector<IncidentZenithNode> zenithNodes(const StageContext& ctx, const Texture2D& optical_depth, double r) {
  static const GaussLegendreRule side_rule = gaussLegendreRule(kDensitySideNodes);
  static const GaussLegendreRule band_rule = gaussLegendreRule(kDensityHorizonBandNodes);
  const AtmosphereParameters& a = ctx.atmosphere;
  const double horizon_theta = std::acos(tangentZenithCosine(r, a.bottom_radius_m));
  const double sky_band = std::min(kDensityHorizonBand_rad, 0.5 * horizon_theta);
  const double ground_band = std::min(kDensityHorizonBand_rad, 0.5 * (kPi - horizon_theta));
  const double d_phi = 2.0 * kPi / kDensityAzimuths;
  std::vector<IncidentZenithNode> nodes;
  struct Piece {
    double from, to;
    const GaussLegendreRule& rule;
  };
  for (const Piece& piece :
       {Piece{0.0, horizon_theta - sky_band, side_rule}, Piece{horizon_theta - sky_band, horizon_theta, band_rule},
        Piece{horizon_theta, horizon_theta + ground_band, band_rule},
        Piece{horizon_theta + ground_band, kPi, side_rule}}) {
    forEachGaussLegendreNode(piece.rule, piece.from, piece.to, [&](double theta, double weight) {
      IncidentZenithNode n;
      n.cos_theta = std::cos(theta);
      n.sin_theta = std::sin(theta);
      n.solid_angle_sr = n.sin_theta * weight * d_phi;
      n.hits_ground = rayIntersectsSphere(r, n.cos_theta, a.bottom_radius_m);
      if (n.hits_ground) {
        const double d = distanceToInnerSphere(r, n.cos_theta, a.bottom_radius_m);
        n.ground_transmittance = glm::exp(-ctx.sampler.opticalDepthAlongRay(optical_depth, r, n.cos_theta, d, true));
        const double horizontal = n.sin_theta * d, vertical = r + n.cos_theta * d;
        const double length = std::sqrt(horizontal * horizontal + vertical * vertical);
        n.ground_up_horizontal = horizontal / length;
        n.ground_up_vertical = vertical / length;
      }
      nodes.push_back(n);
    });
  }
  return nodes;
}

// cos(m * 2 pi k / kPhaseTransformAzimuths) for k = 0 .. half the circle.
struct TransformCosines {
  std::array<std::array<double, kAzimuthModes>, kPhaseTransformAzimuths / 2 + 1> value;
  TransformCosines() {
    for (size_t k = 0; k < value.size(); ++k) {
      for (int m = 0; m < kAzimuthModes; ++m) value[k][m] = std::cos(m * 2.0 * kPi * k / kPhaseTransformAzimuths);
    }
  }
};

// Cosine modes c_m of an even function of azimuth f(phi) = sum_m c_m cos(m phi),
// from its samples at k 2 pi / N, k = 0 .. N / 2 (the other half mirrors).
void cosineModes(const std::array<double, kPhaseTransformAzimuths / 2 + 1>& samples, const TransformCosines& cosines,
                 float* modes) {
  std::array<double, kAzimuthModes> sum{};
  for (size_t k = 0; k < samples.size(); ++k) {
    const double weight = (k == 0 || k + 1 == samples.size()) ? samples[k] : 2.0 * samples[k];
    for (int m = 0; m < kAzimuthModes; ++m) sum[m] += weight * cosines.value[k][m];
  }
  for (int m = 0; m < kAzimuthModes; ++m) {
    modes[m] = static_cast<float>(sum[m] * (m == 0 ? 1.0 : 2.0) / kPhaseTransformAzimuths);
  }
}

}  // namespace

ScatteringDensityKernel makeScatteringDensityKernel(const StageContext& ctx, const Texture2D& optical_depth) {
  const ScatteringSizes& s = ctx.sampler.scatteringSizes();
  const CornetteShanksPhase mie_phase(ctx.atmosphere.mie_phase_g);
  static const TransformCosines cosines;
  ScatteringDensityKernel kernel;
  kernel.altitudes.resize(s.r);
#pragma omp parallel for schedule(dynamic)
  for (int i_r = 0; i_r < s.r; ++i_r) {
    DensityKernelAltitude& k = kernel.altitudes[i_r];
    k.nodes = zenithNodes(ctx, optical_depth, rFromScatteringTexel(ctx.sampler.domain(), s, i_r));
    k.rayleigh_modes.resize(static_cast<size_t>(s.mu) * kDensityZenithNodes * kRayleighAzimuthModes);
    k.mie_modes.resize(static_cast<size_t>(s.mu) * kDensityZenithNodes * kAzimuthModes);
    std::array<double, kPhaseTransformAzimuths / 2 + 1> mie_shape{};
    for (int i_mu = 0; i_mu < s.mu; ++i_mu) {
      const double view_cos = muFromDensityTexel(i_mu, s.mu);
      const double view_sin = safeSqrt(1.0 - view_cos * view_cos);
      for (int i = 0; i < kDensityZenithNodes; ++i) {
        // cos(angle) = a + b cos(azimuth difference).
        const double a = view_cos * k.nodes[i].cos_theta;
        const double b = view_sin * k.nodes[i].sin_theta;
        const size_t pair = static_cast<size_t>(i_mu) * kDensityZenithNodes + i;
        // Rayleigh: 1 + (a + b cos)^2 = 1 + a^2 + b^2 / 2 + 2 a b cos + b^2 / 2 cos 2.
        float* rayleigh = &k.rayleigh_modes[pair * kRayleighAzimuthModes];
        rayleigh[0] = static_cast<float>(1.0 + a * a + 0.5 * b * b);
        rayleigh[1] = static_cast<float>(2.0 * a * b);
        rayleigh[2] = static_cast<float>(0.5 * b * b);
        // Cornette-Shanks without its normalisation.
        for (size_t j = 0; j < mie_shape.size(); ++j) mie_shape[j] = mie_phase.shape(a + b * cosines.value[j][1]);
        cosineModes(mie_shape, cosines, &k.mie_modes[pair * kAzimuthModes]);
      }
    }
    ctx.progress.advance(1);
  }
  return kernel;
}

}  // namespace skybake
