// The local frame the command-line tools describe scenes in: the camera
// above the planet's +z pole, z up; azimuths measured from +x toward +y, the
// sun's azimuth 0 unless given.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

#include "runtime/phase_functions.h"

namespace skybake {

inline glm::dvec3 directionFromZenithAzimuthDeg(double zenith_deg, double azimuth_deg) {
  const double t = zenith_deg * (kPi / 180.0);
  const double p = azimuth_deg * (kPi / 180.0);
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// A texel's (mu, mu_s, nu) in the same frame: the view in the x-z plane at
// zenith cosine mu, the sun at zenith cosine mu_s making cosine nu with it
// (nu outside the range the two zenith angles allow is taken at its edge).
inline glm::dvec3 directionFromZenithCosine(double mu) {
  return {std::sqrt(std::max(0.0, 1.0 - mu * mu)), 0.0, mu};
}

inline glm::dvec3 sunDirectionInViewFrame(double mu, double mu_s, double nu) {
  const double view_sin = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  const double sun_sin = std::sqrt(std::max(0.0, 1.0 - mu_s * mu_s));
  const double x = view_sin > 0.0 ? std::clamp((nu - mu * mu_s) / view_sin, -sun_sin, sun_sin) : sun_sin;
  return {x, std::sqrt(std::max(0.0, sun_sin * sun_sin - x * x)), mu_s};
}

inline glm::dvec3 cameraAtAltitude(double bottom_radius_m, double altitude_m) {
  return {0.0, 0.0, bottom_radius_m + altitude_m};
}

}  // namespace skybake
