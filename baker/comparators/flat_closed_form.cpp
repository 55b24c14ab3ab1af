#include "baker/comparators/flat_closed_form.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace skybake {
namespace {

// Scale height of a profile's first layer if it is exponential; a fallback
// (Earth's Rayleigh) otherwise.
double scaleHeight(const DensityProfile& p, double fallback) {
  if (!p.empty() && p[0].exp_term > 0.0 && p[0].exp_scale < 0.0) return -1.0 / p[0].exp_scale;
  return fallback;
}

// Below this view cosine the flat formula's path to infinity is meaningless.
constexpr double kMinViewCosine = 0.0175;  // 1 deg above the horizontal

}  // namespace

FlatClosedFormSingleScattering::FlatClosedFormSingleScattering(const AtmosphereParameters& a)
    : a_(a),
      rayleigh_scale_height_m_(scaleHeight(a.rayleigh_density, 8000.0)),
      mie_scale_height_m_(scaleHeight(a.mie_density, 1200.0)) {}

RadianceAndTransmittance FlatClosedFormSingleScattering::received(const glm::dvec3& camera, const glm::dvec3& view,
                                                                  const glm::dvec3& sun) const {
  const double r = glm::length(camera);
  const glm::dvec3 up = camera / r;
  const double h = std::max(r - a_.bottom_radius_m, 0.0);
  const double s = glm::dot(up, sun);
  const double v = std::max(glm::dot(up, view), kMinViewCosine);
  const double nu = glm::dot(view, sun);
  const double hr = rayleigh_scale_height_m_, hm = mie_scale_height_m_;
  const SpectrumD rayleigh_column = SpectrumD(a_.rayleigh_scattering) * (hr * std::exp(-h / hr));
  const SpectrumD mie_column = SpectrumD(a_.mie_scattering) * (hm * std::exp(-h / hm));
  const SpectrumD extinction_column = rayleigh_column + SpectrumD(a_.mie_extinction) * (hm * std::exp(-h / hm)) +
                                      SpectrumD(a_.absorption_extinction) * (hr * std::exp(-h / hr));
  const SpectrumD transmittance = glm::exp(-extinction_column / v);
  if (s <= 0.0) return {Spectrum(0.0f), Spectrum(transmittance)};
  SpectrumD path(0.0);
  for (int c = 0; c < kMaxChannels; ++c) {
    const double b = extinction_column[c];
    if (b <= 0.0) continue;
    path[c] = std::abs(s - v) < 1e-9 ? (1.0 / v) * std::exp(-b / v)
                                     : s * (std::exp(-b / s) - std::exp(-b / v)) / (b * (s - v));
  }
  const SpectrumD radiance =
      SpectrumD(a_.sun_irradiance) * path *
      (rayleigh_column * rayleighPhase(nu) + mie_column * cornetteShanksPhase(a_.mie_phase_g, nu));
  return {Spectrum(radiance), Spectrum(transmittance)};
}

}  // namespace skybake
