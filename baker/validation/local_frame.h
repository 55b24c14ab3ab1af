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

inline glm::dvec3 cameraAtAltitude(double bottom_radius_m, double altitude_m) {
  return {0.0, 0.0, bottom_radius_m + altitude_m};
}

}  // namespace skybake
