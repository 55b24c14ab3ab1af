// Light scattered more than once during a solar eclipse: an approximation
// (docs/ECLIPSES.md). The tables hold the multiple scattering of an
// uneclipsed sun. Scaling it by the visible part of the sun at the camera
// would make totality black; the light there comes from sunlit air outside
// the umbra, tens to hundreds of kilometres away, scattered toward the
// camera's air and on to the camera. So the tables' multiple scattering (and
// the sky's irradiance) are scaled instead by the sun's visible fraction
// averaged over the camera's neighbourhood, weighted by how far light
// travels to it before scattering:
//
//   F = integral over the plane across the sun through the camera of
//       f(x) w(|x|) dA,   w(rho) = exp(-rho / l) / (2 pi l rho),
//
// f the visible fraction (Moon::visibleSunFraction) and l the mean free path
// at the camera's altitude, 1 / extinction, per channel. w is the share of
// the light arriving at the camera's air along each direction in the plane
// that was last scattered at distance rho (radiance along a ray gathers
// scattering at every distance, dimmed by exp(-rho / l)), spread over the
// directions evenly; it integrates to 1, so F = 1 with no moon, F = f for a
// uniform f, and F is 0 only if the sun is hidden everywhere in reach.
#pragma once

#include <glm/vec3.hpp>

#include "data_formats/atmosphere_parameters.h"
#include "runtime/moon_occluder.h"

namespace skybake {

// Rings and directions of the neighbourhood's quadrature. The rings' radii
// grow geometrically from kEclipseInnerRing_m to kEclipseOuterRingMeanFreePaths
// times the longest mean free path (light from further is dimmed by e^-30),
// at most 1.22 times per ring at these counts. f is linear between rings
// but for the umbra's edge, where it rises as the distance past it to the
// power 3/2: there the rings overestimate F of a camera in totality by 2 %
// at 64 rings (1 % at 96) against a brute-force integral
// (tests/runtime/eclipse_test.cpp). Eight directions per ring resolve the
// penumbra's gradient across a ring (twelve changed F by under 1e-3).
inline constexpr int kEclipseNeighbourhoodRings = 64;
inline constexpr int kEclipseNeighbourhoodDirections = 8;
inline constexpr double kEclipseInnerRing_m = 300.0;
inline constexpr double kEclipseOuterRingMeanFreePaths = 30.0;

// The mean free path, m, from an extinction coefficient (m^-1); an
// extinction below 1 / `longest_m` (thin air, or none) gives `longest_m`:
// light goes no further than the atmosphere is long.
inline double meanFreePath(double extinction_per_m, double longest_m) {
  return extinction_per_m * longest_m > 1.0 ? 1.0 / extinction_per_m : longest_m;
}

// F above, per channel, for the neighbourhood of `point` (in the atmosphere)
// under the sun at unit `sun_dir`.
Spectrum eclipseSkylightFraction(const AtmosphereParameters& a, const Moon& moon, const glm::dvec3& point,
                                 const glm::dvec3& sun_dir);

}  // namespace skybake
