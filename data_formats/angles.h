// Pi, the conversions between degrees and radians, and unit vectors from
// angles: the one definition of each that every layer uses (degrees appear
// only in configs and flags that say so; physics works in radians and
// cosines).
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

namespace skybake {

inline constexpr double kPi = 3.14159265358979323846;

constexpr double radiansFromDegrees(double degrees) { return degrees * (kPi / 180.0); }
constexpr double degreesFromRadians(double radians) { return radians * (180.0 / kPi); }

// Unit vectors in a frame whose zenith is +z and whose azimuths run from +x
// toward +y (the local frame of the command line, images and tests: the
// camera above the planet's +z pole).
inline glm::dvec3 directionFromZenithAzimuth(double zenith_rad, double azimuth_rad) {
  return {std::sin(zenith_rad) * std::cos(azimuth_rad), std::sin(zenith_rad) * std::sin(azimuth_rad),
          std::cos(zenith_rad)};
}
// The same from the elevation above the horizontal plane (90 deg minus the
// zenith angle), without the rounding of that subtraction.
inline glm::dvec3 directionFromElevationAzimuth(double elevation_rad, double azimuth_rad) {
  return {std::cos(elevation_rad) * std::cos(azimuth_rad), std::cos(elevation_rad) * std::sin(azimuth_rad),
          std::sin(elevation_rad)};
}
// The same from the zenith angle's cosine, in [-1, 1].
inline glm::dvec3 directionFromZenithCosineAzimuth(double zenith_cosine, double azimuth_rad) {
  const double sine = std::sqrt(std::max(1.0 - zenith_cosine * zenith_cosine, 0.0));
  return {sine * std::cos(azimuth_rad), sine * std::sin(azimuth_rad), zenith_cosine};
}

}  // namespace skybake
