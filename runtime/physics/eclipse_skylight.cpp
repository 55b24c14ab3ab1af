#include "runtime/physics/eclipse_skylight.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "data_formats/parameterization/ray_sphere.h"
#include "runtime/physics/atmosphere_media.h"

namespace skybake {

Spectrum eclipseSkylightFraction(const AtmosphereParameters& a, const Moon& moon, const glm::dvec3& point,
                                 const glm::dvec3& sun_dir, int elevations, int azimuths, int distances) {
  if (!moon.present()) return Spectrum(1.0f);
  const AtmosphereMedia media(a);
  const double alpha = a.sun_angular_radius_rad;
  const double length = glm::length(point);
  const double r = std::clamp(length, a.bottom_radius_m, a.top_radius_m);
  const glm::dvec3 up = length > 0.0 ? point / length : glm::dvec3(0.0, 0.0, 1.0);
  const glm::dvec3 x = up * r;
  const glm::dvec3 helper = std::abs(up.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 east = glm::normalize(glm::cross(helper, up)), north = glm::cross(up, east);
  SpectrumD lit(0.0), all(0.0);
  // Zenith cosines from u at the midpoints of `elevations` equal steps over
  // [-1, 1], mu = h + (1 -+ h) u |u| about the horizon's h: dense near it,
  // where the paths through the air are longest; each direction weighs its
  // share of the sphere, dmu = 2 (1 -+ h) |u| du.
  const double horizon_mu = tangentZenithCosine(r, a.bottom_radius_m);
  for (int e = 0; e < elevations; ++e) {
    const double u = -1.0 + 2.0 * (e + 0.5) / elevations;
    const double side = u < 0.0 ? 1.0 + horizon_mu : 1.0 - horizon_mu;
    const double mu = horizon_mu + side * u * std::abs(u);
    const double solid_angle = 2.0 * side * std::abs(u) * (2.0 / elevations);
    const double sin_theta = safeSqrt(1.0 - mu * mu);
    for (int j = 0; j < azimuths; ++j) {
      // Each band turned by half a step against the last: no azimuth is
      // favoured throughout.
      const double phi = 2.0 * kPi * (j + 0.5 * (e % 2)) / azimuths;
      const glm::dvec3 w = up * mu + (east * std::cos(phi) + north * std::sin(phi)) * sin_theta;
      const bool ground = rayIntersectsSphere(r, mu, a.bottom_radius_m);
      const double end_m = distanceToAtmosphereEnd(r, mu, a.bottom_radius_m, a.top_radius_m, ground);
      if (!(end_m > kEclipseFirstDistance_m)) continue;
      const double growth = std::pow(end_m / kEclipseFirstDistance_m, 1.0 / (distances - 1));
      SpectrumD depth(0.0);
      double start = 0.0;
      for (int k = 0; k < distances; ++k) {
        const double stop = k + 1 == distances ? end_m : kEclipseFirstDistance_m * std::pow(growth, k);
        const double mid = 0.5 * (start + stop), step = stop - start;
        const glm::dvec3 p = x + w * mid;
        const double altitude = std::max(glm::length(p) - a.bottom_radius_m, 0.0);
        const SpectrumD scattering = SpectrumD(a.rayleigh_scattering) * media.rayleighDensity(altitude) +
                                     SpectrumD(a.mie_scattering) * media.mieDensity(altitude);
        // What dims the light on its way back to x: absorption, and the share
        // of scattering that sends it out of the multiply scattered field.
        const SpectrumD extinction = media.extinction(altitude) - scattering * kEclipseRedirectedScatteringShare;
        // Optical depth to the step's middle: the steps before plus half this one.
        const SpectrumD weight = scattering * glm::exp(-(depth + extinction * (0.5 * step))) * (step * solid_angle);
        depth += extinction * step;
        all += weight;
        lit += weight * moon.visibleSunFraction(p, sun_dir, alpha);
        start = stop;
      }
    }
  }
  const double here = moon.visibleSunFraction(x, sun_dir, alpha);
  Spectrum out(0.0f);
  for (int c = 0; c < a.channelCount(); ++c) {
    out[c] = static_cast<float>(all[c] > 0.0 ? std::clamp(lit[c] / all[c], 0.0, 1.0) : here);
  }
  return out;
}

}  // namespace skybake
