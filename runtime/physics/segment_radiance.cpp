#include "runtime/physics/segment_radiance.h"

#include <algorithm>

#include "runtime/physics/atmosphere_media.h"
#include "runtime/physics/phase_functions.h"
#include "runtime/physics/ray_quadrature.h"

namespace skybake {

// The optical depth along the segment is integrated from the density
// profiles: a difference of two tabulated depths to the top is two values
// near 30 at the horizon whose difference over 1 km is 0.04, and table error
// would dominate it.
RadianceAndTransmittance directSegmentRadiance(const TableSampler& sampler, const BakeTables& t,
                                               const AtmosphereParameters& a,
                                               const MultipleScatteringPhase& multiple_shape, double r, double mu,
                                               double mu_s, double nu, double length, int subintervals,
                                               bool with_single) {
  const AtmosphereDomain& domain = sampler.domain();
  const AtmosphereMedia media(a);
  const float rayleigh_phase = static_cast<float>(rayleighPhase(nu));
  const float mie_phase = static_cast<float>(cornetteShanksPhase(a.mie_phase_g, nu));
  const double multiple_peak = multiple_shape.peakAt(nu);
  auto altitudeAt = [&](double d) {
    return std::clamp(radiusAlongRay(r, mu, d), domain.bottom_radius_m, domain.top_radius_m) - domain.bottom_radius_m;
  };
  Spectrum sum(0.0f);
  const SpectrumD depth = forEachOpticallyThinNodeWithIntegral<SpectrumD>(
      length, subintervals, -r * mu, [&](double d) { return media.extinction(altitudeAt(d)); }, largestChannel,
      [&](double d, double w, const SpectrumD& depth_to_d) {
        const double r_d = domain.bottom_radius_m + altitudeAt(d);
        const double mu_d = cosineAlongRay(r, mu, d, r_d);
        const double mu_s_d = clampCosine((r * mu_s + d * nu) / r_d);
        const double altitude = r_d - domain.bottom_radius_m;
        const Spectrum single_source =
            with_single
                ? (a.rayleigh_scattering * (static_cast<float>(media.rayleighDensity(altitude)) * rayleigh_phase) +
                   a.mie_scattering * (static_cast<float>(media.mieDensity(altitude)) * mie_phase)) *
                      (a.sun_irradiance *
                       sampler.transmittanceToSun(t.optical_depth, r_d, mu_s_d, a.sun_angular_radius_rad))
                : Spectrum(0.0f);
        const Spectrum multiple_source =
            sampler.multipleDensity(t.multiple_density, r_d, mu_d, mu_s_d, nu) *
            MultipleScatteringPhase::withPeak(multiple_shape.peakWeightAt(altitude), multiple_peak);
        sum += (single_source + multiple_source) * Spectrum(glm::exp(-depth_to_d)) * static_cast<float>(w);
      });
  return {sum, Spectrum(glm::exp(-depth))};
}

}  // namespace skybake
