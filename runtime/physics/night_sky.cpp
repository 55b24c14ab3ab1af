#include "runtime/physics/night_sky.h"

#include <algorithm>
#include <cmath>

namespace skybake {

Spectrum NightContinuation::scaleBelowEdge(double mu_s) const {
  const double x = kernel::skybakeNightScaleBase(mu_s, edge_mu_s, edge_sin, inverse_tan_half_span);
  Spectrum s(0.0f);
  for (int c = 0; c < kMaxChannels; ++c) s[c] = static_cast<float>(std::pow(x, static_cast<double>(exponent[c])));
  return s;
}

NightContinuation nightContinuationOf(const AtmosphereDomain& domain, const Texture2D& irradiance) {
  NightContinuation night;
  night.edge_mu_s = clampCosine(domain.mu_s_min);
  night.edge_sin = safeSqrt(1.0 - night.edge_mu_s * night.edge_mu_s);
  const double edge_zenith_rad = std::acos(night.edge_mu_s);
  const double dark_rad = darkSunZenithRad(domain.bottom_radius_m, domain.top_radius_m);
  // An edge beyond the dark angle (a bake to a lower sun than physics needs)
  // falls on to the nadir instead; an edge at the nadir has nothing below.
  const double end_rad = dark_rad > edge_zenith_rad ? dark_rad : kPi;
  if (!(end_rad > edge_zenith_rad)) return night;
  const double tan_half_span = std::tan(0.5 * (end_rad - edge_zenith_rad));
  night.inverse_tan_half_span = 1.0 / tan_half_span;
  if (irradiance.width < 2 || irradiance.height < 1 || irradiance.texels.empty()) return night;
  // The ground's sky irradiance at the two lowest sun texels (the first sits
  // exactly on the edge): its logarithmic fall-off per radian of depression.
  const double zenith_above_rad = std::acos(clampCosine(muSFromIrradianceTexel(domain, irradiance.width, 1)));
  const double step_rad = edge_zenith_rad - zenith_above_rad;
  for (int c = 0; c < kMaxChannels; ++c) {
    const double at_edge = irradiance.at(0, 0)[c], above = irradiance.at(1, 0)[c];
    const double fall_off_per_rad =
        step_rad > 0.0 && at_edge > 0.0 && above > at_edge ? std::log(above / at_edge) / step_rad : 0.0;
    night.exponent[c] = static_cast<float>(std::max(2.0 * fall_off_per_rad * tan_half_span, 1.0));
  }
  return night;
}

}  // namespace skybake
