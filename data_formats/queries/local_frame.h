// The local frame the command-line tools describe scenes in: the camera
// above the planet's +z pole, z up; azimuths measured from +x toward +y, the
// sun's azimuth 0 unless given.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

#include "data_formats/angles.h"

namespace skybake {

inline glm::dvec3 directionFromZenithAzimuthDeg(double zenith_deg, double azimuth_deg) {
  return directionFromZenithAzimuth(radiansFromDegrees(zenith_deg), radiansFromDegrees(azimuth_deg));
}

// The point at `altitude_m` above the +z pole. One below the ground is on
// the ground, at any depth (as Sky looks up a camera below the ground): an
// altitude below minus the planet's radius would otherwise land beyond the
// centre, under the opposite pole, where the local frame's up is down.
inline glm::dvec3 cameraAtAltitude(double bottom_radius_m, double altitude_m) {
  return {0.0, 0.0, bottom_radius_m + std::max(altitude_m, 0.0)};
}

}  // namespace skybake
