// Single-scattered radiance by direct integration along a view ray, no
// tables: the truth the runtime's table lookups and ray integrals are tested
// against. Gauss nodes along the ray (to its end, or to `distance_m` when
// > 0), optical depths by quadrature of the density profiles (validated
// against closed forms in the baker tests), the part of the sun disk above
// each point's horizon as the bake counts it (sunDiskVisibleFraction), times
// what a moon leaves of it there (none by default).
#pragma once

#include <glm/geometric.hpp>

#include "baker/numerics/optical_depth_integral.h"
#include "data_formats/config/atmosphere_parameters.h"
#include "data_formats/parameterization/ray_sphere.h"
#include "runtime/physics/atmosphere_media.h"
#include "runtime/physics/moon_occluder.h"
#include "runtime/physics/phase_functions.h"
#include "runtime/physics/ray_quadrature.h"
#include "runtime/physics/sun_disk.h"

namespace skybake {

// `camera` in metres from the planet's centre, `view` and `sun` unit;
// `segments` sub-intervals of 4 Gauss nodes each.
inline Spectrum directSingleScatteringFrom(const AtmosphereParameters& a, const glm::dvec3& camera,
                                           const glm::dvec3& view, const glm::dvec3& sun, double distance_m,
                                           int segments, const Moon& moon = Moon{}) {
  const AtmosphereMedia media(a);
  const double r = glm::length(camera), mu = glm::dot(camera, view) / r, mu_s = glm::dot(camera, sun) / r;
  const double nu = glm::dot(view, sun);
  const bool ground = rayIntersectsSphere(r, mu, a.bottom_radius_m);
  const double length = distance_m > 0.0 ? distance_m
                        : ground         ? distanceToInnerSphere(r, mu, a.bottom_radius_m)
                                         : distanceToOuterSphere(r, mu, a.top_radius_m);
  const double p_r = rayleighPhase(nu), p_m = cornetteShanksPhase(a.mie_phase_g, nu);
  SpectrumD sum(0.0);
  forEachQuadratureNode(0.0, length, segments, [&](double t, double w) {
    const double r_t = radiusAlongRay(r, mu, t);
    const double mu_s_t = (r * mu_s + t * nu) / r_t;
    const double visible =
        sunDiskVisibleFraction(mu_s_t - tangentZenithCosine(r_t, a.bottom_radius_m),
                               sunDiskHalfSizeAtHorizon(a.bottom_radius_m, r_t, a.sun_angular_radius_rad)) *
        moon.visibleSunFraction(camera + view * t, sun, a.sun_angular_radius_rad);
    if (visible <= 0.0) return;  // in the planet's shadow, or the moon's
    const SpectrumD depth =
        integrateOpticalDepthAlongRay(media, r, mu, t) + integrateOpticalDepthToTop(media, r_t, mu_s_t);
    const double h = r_t - a.bottom_radius_m;
    const SpectrumD scattering = SpectrumD(a.rayleigh_scattering) * (media.rayleighDensity(h) * p_r) +
                                 SpectrumD(a.mie_scattering) * (media.mieDensity(h) * p_m);
    sum += scattering * glm::exp(-depth) * (w * visible);
  });
  return Spectrum(sum * SpectrumD(a.sun_irradiance));
}

}  // namespace skybake
