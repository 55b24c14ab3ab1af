// Light scattered more than once during a solar eclipse: an approximation
// (docs/ECLIPSES.md). The tables hold the multiple scattering of an
// uneclipsed sun. Scaling it by the visible part of the sun at the camera
// would make totality black; the light there comes from sunlit air outside
// the umbra, tens to hundreds of kilometres away, scattered toward the
// camera's air and on to the camera. So the tables' multiple scattering (and
// the sky's irradiance) are scaled instead by the sun's visible fraction
// averaged over where the light reaching the camera's air was last
// scattered:
//
//   F = sum over directions w of  integral ds  f(x + s w) k(s)
//       / the same without f,     k(s) = beta_s(x + s w) exp(-tau'(x, x + s w)),
//
// f the visible fraction (Moon::visibleSunFraction) at each point, beta_s
// the scattering coefficient there and tau' an optical depth back to x, per
// channel: k is the share of the light arriving at x along w that was
// scattered at distance s. Were tau' the whole optical depth, k would follow
// the light scattered twice; but light scattered off the line to x is not
// lost to x's surroundings, and part of it gets there after further
// scattering, so multiply scattered light reaches further than once
// scattered light does. tau' counts absorption and the share
// 1 - kEclipseRedirectedScatteringShare of scattering. Directions are taken
// evenly over the sphere, the phase functions and the sun's direction left
// out. So F = 1 with no moon, F = f for a uniform f, and F in totality is
// the share of the air light reaches x from that the sun still lights.
#pragma once

#include <glm/vec3.hpp>

#include "data_formats/config/atmosphere_parameters.h"
#include "runtime/physics/moon_occluder.h"

namespace skybake {

// Directions (bands of zenith cosine, denser near the horizon, times
// azimuths) and distances along each of the kernel's quadrature. Distances grow geometrically from
// kEclipseFirstDistance_m to where the direction leaves the atmosphere or
// meets the ground, by at most 1.3 times per step (midpoints); the umbra's
// edge, where f starts to rise, is resolved to that. The counts against a
// brute-force kernel: tests/runtime/eclipse_test.cpp.
inline constexpr int kEclipseKernelElevations = 16;
inline constexpr int kEclipseKernelAzimuths = 8;
inline constexpr int kEclipseKernelDistances = 32;
inline constexpr double kEclipseFirstDistance_m = 200.0;
// The share of scattering along the way that the kernel does not count as
// a loss (tau' above). A calibration, not a derivation: against the path
// traced reference at the centre of a total eclipse's umbra (sun 40 deg
// high, moon 0.28 deg, docs/ECLIPSES.md), 0 (the light scattered twice
// alone) makes the zenith at 440 nm about 5 times too dark on the ground,
// 1 (no scattering loss) about 3 times too bright; 0.55 puts the ground's
// zenith at 1.18 / 1.13 / 0.77 of the reference at 680 / 550 / 440 nm (at
// 10 km it is 2.2 / 1.8 / 1.2: see docs/ECLIPSES.md).
inline constexpr double kEclipseRedirectedScatteringShare = 0.55;

// F above, per channel, for the neighbourhood of `point` (in the atmosphere)
// under the sun at unit `sun_dir`. The counts set the quadrature (the
// defaults above; tests compare with finer ones).
Spectrum eclipseSkylightFraction(const AtmosphereParameters& a, const Moon& moon, const glm::dvec3& point,
                                 const glm::dvec3& sun_dir, int elevations = kEclipseKernelElevations,
                                 int azimuths = kEclipseKernelAzimuths, int distances = kEclipseKernelDistances);

}  // namespace skybake
