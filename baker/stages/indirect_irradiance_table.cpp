#include <omp.h>

#include <optional>
#include <vector>

#include "baker/stages/indirect_irradiance_table.h"
#include "runtime/physics/single_scattering_ray.h"
#include "runtime/sky_lookup_constants.h"

namespace skybake {
namespace {

// The directions of the upper hemisphere the sky irradiance sums: midpoint
// rings in zenith angle, kZenithSamples over [0, 90 deg - band] and
// kHorizonBandSamples over the band just above the horizon, each ring with
// kAzimuthSamples azimuths. In twilight, seen from altitude, the sky's light
// comes from a glow a few degrees above the sunward horizon; 32 even rings
// put one node in it and read 4 to 8 % high at sun 98 deg from 28 to 56 km
// (0.2 to 0.5 % by day); with the band every case is within 0.7 % of 1024
// rings (docs/MEASUREMENTS.md).
constexpr int kZenithSamples = 32;
constexpr int kHorizonBandSamples = 8;
constexpr double kHorizonBand_rad = 5.0 * kPi / 180.0;
constexpr int kAzimuthSamples = 64;

struct ZenithRing {
  double mu;
  double sin_theta;
  double weight;  // cos(theta) for the horizontal surface times the ring's solid angle per azimuth
};

std::vector<ZenithRing> zenithRings() {
  std::vector<ZenithRing> rings;
  const double d_phi = 2.0 * kPi / kAzimuthSamples;
  auto add = [&](double theta_min, double theta_max, int count) {
    const double d_theta = (theta_max - theta_min) / count;
    for (int i = 0; i < count; ++i) {
      const double theta = theta_min + (i + 0.5) * d_theta;
      rings.push_back({std::cos(theta), std::sin(theta), std::cos(theta) * std::sin(theta) * d_theta * d_phi});
    }
  };
  add(0.0, kPi / 2.0 - kHorizonBand_rad, kZenithSamples);
  add(kPi / 2.0 - kHorizonBand_rad, kPi / 2.0, kHorizonBandSamples);
  return rings;
}

}  // namespace

Texture2D computeIndirectIrradianceTable(const StageContext& ctx, const Texture2D& optical_depth,
                                         const OrderRadiance& order) {
  const TextureSizes& s = ctx.sampler.sizes();
  const AtmosphereParameters& a = ctx.atmosphere;
  Texture2D table(s.irradiance_mu_s, s.irradiance_r);
  const std::vector<ZenithRing> rings = zenithRings();
  // Azimuths phi and 2 pi - phi see the sun at the same angle: half the
  // ring, counted twice.
  std::vector<double> cos_phi(kAzimuthSamples / 2);
  for (int j = 0; j < kAzimuthSamples / 2; ++j) cos_phi[j] = std::cos((j + 0.5) * 2.0 * kPi / kAzimuthSamples);
#pragma omp parallel
  {
    // The directions of one zenith ring share (r, mu, mu_s): the tables are
    // interpolated there once and each azimuth only blends across nu.
    OrderRadianceAlongNu ring_radiance(order, ctx.sampler, a.mie_phase_g);
#pragma omp for schedule(dynamic)
    for (int i_r = 0; i_r < table.height; ++i_r) {
      for (int i_mu_s = 0; i_mu_s < table.width; ++i_mu_s) {
        const RMuS rm = irradianceTexelConfig(ctx.sampler.domain(), table.width, table.height, i_mu_s, i_r);
        const double sun_x = safeSqrt(1.0 - rm.mu_s * rm.mu_s);
        // With the sun below the horizon the sky lookups integrate single
        // scattering along each view ray instead of reading its tables
        // (runtime/sky_twilight.cpp), which miss the planet's shadow there;
        // order 1 of the sky irradiance, the sum of that sky, does the same,
        // with the lookups' rule.
        const double integrated_weight = order.order == 1 ? integratedSingleScatteringWeight(rm.mu_s) : 0.0;
        SpectrumD sum(0.0);
        for (const ZenithRing& ring : rings) {
          const double length = distanceToAtmosphereEnd(rm.r, ring.mu, a.bottom_radius_m, a.top_radius_m, false);
          ring_radiance.moveTo(rm.r, ring.mu, rm.mu_s, false);
          // The ring's view ray, shared by its azimuths' integrals.
          std::optional<SingleScatteringAlongRay> along_ray;
          if (integrated_weight > 0.0) {
            along_ray.emplace(ctx.sampler, optical_depth, a, rm.r, ring.mu, false, 0.0, length,
                              kLookupSingleScatteringSegments);
          }
          for (int j = 0; j < kAzimuthSamples / 2; ++j) {
            const double nu = clampCosine(ring.sin_theta * cos_phi[j] * sun_x + ring.mu * rm.mu_s);
            SpectrumD radiance(ring_radiance.at(nu));
            if (along_ray) {
              const SingleScattering integrated = along_ray->under(rm.mu_s, nu);
              const SpectrumD integrated_radiance(
                  order.withPhase(integrated.rayleigh, integrated.mie, nu, SpectrumD(0.0), a.mie_phase_g));
              radiance += (integrated_radiance - radiance) * integrated_weight;
            }
            sum += radiance * (2.0 * ring.weight);
          }
        }
        table.at(i_mu_s, i_r) = Spectrum(sum);
      }
      ctx.progress.advance(1);
    }
  }
  return table;
}

}  // namespace skybake
