#include "baker/comparators/ray_marched_single.h"

#include <glm/geometric.hpp>

#include "runtime/physics/atmosphere_media.h"
#include "runtime/physics/atmosphere_ray.h"

namespace skybake {
namespace {

constexpr int kViewSteps = 32;
constexpr int kLightSteps = 8;

}  // namespace

RadianceAndTransmittance RayMarchedSingleScattering::received(const glm::dvec3& camera, const glm::dvec3& view,
                                                              const glm::dvec3& sun) const {
  const AtmosphereMedia media(a_);
  const AtmosphereRay ray = atmosphereRay(a_.bottom_radius_m, a_.top_radius_m, camera, view, 0.0);
  if (!ray.inside) return {Spectrum(0.0f), Spectrum(1.0f)};
  const double nu = glm::dot(view, sun);
  const double p_r = rayleighPhase(nu), p_m = cornetteShanksPhase(a_.mie_phase_g, nu);
  // Optical depth toward the sun by midpoint steps to the top (0 light when
  // the sun ray hits the ground).
  auto sunDepth = [&](const glm::dvec3& p, bool& shadowed) {
    const double r = glm::length(p), mu_s = glm::dot(p, sun) / r;
    shadowed = rayIntersectsSphere(r, mu_s, a_.bottom_radius_m);
    const double length = distanceToOuterSphere(r, mu_s, a_.top_radius_m), ds = length / kLightSteps;
    SpectrumD depth(0.0);
    for (int j = 0; j < kLightSteps; ++j)
      depth += media.extinction(glm::length(p + sun * ((j + 0.5) * ds)) - a_.bottom_radius_m) * ds;
    return depth;
  };
  const double ds = ray.length / kViewSteps;
  SpectrumD view_depth(0.0), radiance(0.0);
  for (int i = 0; i < kViewSteps; ++i) {
    const glm::dvec3 p = ray.origin + view * ((i + 0.5) * ds);
    const double h = glm::length(p) - a_.bottom_radius_m;
    const SpectrumD extinction = media.extinction(h);
    const SpectrumD depth_here = view_depth + extinction * (0.5 * ds);
    view_depth += extinction * ds;
    bool shadowed;
    const SpectrumD sun_depth = sunDepth(p, shadowed);
    if (shadowed) continue;
    radiance += (SpectrumD(a_.rayleigh_scattering) * (media.rayleighDensity(h) * p_r) +
                 SpectrumD(a_.mie_scattering) * (media.mieDensity(h) * p_m)) *
                glm::exp(-(depth_here + sun_depth)) * ds;
  }
  radiance *= SpectrumD(a_.sun_irradiance);
  const SpectrumD transmittance = glm::exp(-view_depth);
  if (ray.ends_on_ground) {
    const glm::dvec3 g = ray.origin + view * ray.length;
    const double mu_s = glm::dot(glm::normalize(g), sun);
    bool shadowed;
    const SpectrumD sun_depth = sunDepth(g, shadowed);
    if (mu_s > 0.0 && !shadowed) {
      radiance += transmittance * SpectrumD(a_.ground_albedo) * (mu_s / kPi) * SpectrumD(a_.sun_irradiance) *
                  glm::exp(-sun_depth);
    }
  }
  return {Spectrum(radiance), Spectrum(transmittance)};
}

}  // namespace skybake
