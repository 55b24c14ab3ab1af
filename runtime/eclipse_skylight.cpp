#include "runtime/eclipse_skylight.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "data_formats/ray_sphere.h"
#include "runtime/atmosphere_media.h"

namespace skybake {

Spectrum eclipseSkylightFraction(const AtmosphereParameters& a, const Moon& moon, const glm::dvec3& point,
                                 const glm::dvec3& sun_dir) {
  if (!moon.present()) return Spectrum(1.0f);
  const AtmosphereMedia media(a);
  const double r = std::clamp(glm::length(point), a.bottom_radius_m, a.top_radius_m);
  // The longest straight path in the shell: a ray grazing the ground from the top.
  const double longest_m = 2.0 * safeSqrt(a.top_radius_m * a.top_radius_m - a.bottom_radius_m * a.bottom_radius_m);
  const SpectrumD extinction = media.extinction(r - a.bottom_radius_m);
  const int channels = a.channelCount();
  std::array<double, kMaxChannels> free_path{};
  double longest_free_path = 0.0;
  for (int c = 0; c < channels; ++c) {
    free_path[c] = meanFreePath(extinction[c], longest_m);
    longest_free_path = std::max(longest_free_path, free_path[c]);
  }
  // Two axes across the sun.
  const glm::dvec3 helper = std::abs(sun_dir.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 across_u = glm::normalize(glm::cross(helper, sun_dir));
  const glm::dvec3 across_v = glm::cross(sun_dir, across_u);
  const double alpha = a.sun_angular_radius_rad;

  // f averaged over each ring, the point itself at radius 0.
  std::array<double, kEclipseNeighbourhoodRings + 1> radius{}, ring_fraction{};
  ring_fraction[0] = moon.visibleSunFraction(point, sun_dir, alpha);
  const double outer_m = std::max(kEclipseOuterRingMeanFreePaths * longest_free_path, 2.0 * kEclipseInnerRing_m);
  const double growth = std::pow(outer_m / kEclipseInnerRing_m, 1.0 / (kEclipseNeighbourhoodRings - 1));
  for (int k = 1; k <= kEclipseNeighbourhoodRings; ++k) {
    radius[k] = kEclipseInnerRing_m * std::pow(growth, k - 1);
    // Each ring turned by half a step against the last: no direction is
    // favoured throughout.
    const double offset = 0.5 * (k % 2);
    double sum = 0.0;
    for (int j = 0; j < kEclipseNeighbourhoodDirections; ++j) {
      const double phi = 2.0 * kPi * (j + offset) / kEclipseNeighbourhoodDirections;
      const glm::dvec3 p = point + (across_u * std::cos(phi) + across_v * std::sin(phi)) * radius[k];
      sum += moon.visibleSunFraction(p, sun_dir, alpha);
    }
    ring_fraction[k] = sum / kEclipseNeighbourhoodDirections;
  }

  // Per channel, the integral of the piecewise linear f against the radial
  // density exp(-rho / l) / l, exactly on each interval; beyond the last ring
  // f is held.
  Spectrum out(0.0f);
  for (int c = 0; c < channels; ++c) {
    const double l = free_path[c];
    double total = 0.0;
    double weight_left = 1.0;  // exp(-radius[k] / l)
    for (int k = 0; k < kEclipseNeighbourhoodRings; ++k) {
      const double width = radius[k + 1] - radius[k];
      const double weight_right = std::exp(-radius[k + 1] / l);
      const double mass = weight_left * -std::expm1(-width / l);  // integral of the density over the interval
      // Integral of (rho - radius[k]) times the density over it, over width.
      const double ramp = width > 0.0 ? (l * mass - width * weight_right) / width : 0.0;
      total += ring_fraction[k] * mass + (ring_fraction[k + 1] - ring_fraction[k]) * ramp;
      weight_left = weight_right;
    }
    total += ring_fraction[kEclipseNeighbourhoodRings] * weight_left;
    out[c] = static_cast<float>(std::clamp(total, 0.0, 1.0));
  }
  return out;
}

}  // namespace skybake
