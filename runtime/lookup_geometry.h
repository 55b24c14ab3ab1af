// The geometry every Sky lookup accepts, checked where a lookup starts
// (runtime/README.md, "Geometry"):
//  - refused with Error(BadInput), naming the argument and its value: a
//    non-finite component in any position or direction, a direction of
//    length 0, a moon with a negative or non-finite radius or a non-finite
//    centre, a negative or non-finite shadow length;
//  - a camera inside the moon sees its dark inside: radiance 0,
//    transmittance 0;
//  - normalised: a direction of any other length (scaled by its largest
//    component first, so that lengths of 1e-300 or 1e300 neither underflow
//    nor overflow);
//  - clamped: a position farther than kMaxPositionDistance_m from the
//    planet's centre is moved toward the centre to that distance, and one
//    below the ground at any depth is on the ground directly above it
//    (atmosphereRay and the irradiance lookups).
// Without these, NaN anywhere gave NaN or a plausible 0 or 1, a view of
// length 1e-30 read another direction's radiance, and a camera at 1e300 m
// gave NaN.
#pragma once

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "runtime/physics/moon_occluder.h"

namespace skybake {

// Farther than this a position is moved in to it. At 1e12 m (7 AU) a
// double still places a point to 1e-4 m, so a ray from there is aimed at
// the atmosphere as exactly as from nearby, and the atmosphere of an
// Earth-sized planet spans 13 microradians, less than a pixel of any view;
// at 1e300 m the squares in the ray-sphere test overflowed to NaN.
inline constexpr double kMaxPositionDistance_m = 1e12;

// A direction whose squared length is within this of 1 is used as given:
// normalising it would change a cosine by at most 5e-7, far below the
// tables' interpolation error, and would cost every lookup a square root.
inline constexpr double kUnitLengthTolerance = 1e-6;

// The slow paths, out of line: a direction that is not of unit length, a
// position beyond kMaxPositionDistance_m or not finite.
glm::dvec3 normalisedDirection(const glm::dvec3& d, const char* what);
glm::dvec3 positionWithinReach(const glm::dvec3& p, const char* what);

// `d` as a unit direction, or Error(BadInput) for a non-finite or zero one.
inline glm::dvec3 lookupDirection(const glm::dvec3& d, const char* what) {
  return std::abs(glm::dot(d, d) - 1.0) <= kUnitLengthTolerance ? d : normalisedDirection(d, what);
}

// `p` (metres from the planet's centre) within kMaxPositionDistance_m, or
// Error(BadInput) for a non-finite one.
inline glm::dvec3 lookupPosition(const glm::dvec3& p, const char* what) {
  // Every component within kMax / sqrt(3) keeps |p| within kMax; NaN fails the test.
  constexpr double kComponentBound = kMaxPositionDistance_m / 1.7320508075688772;
  const bool near =
      std::abs(p.x) <= kComponentBound && std::abs(p.y) <= kComponentBound && std::abs(p.z) <= kComponentBound;
  return near ? p : positionWithinReach(p, what);
}

// A view lookup's camera, view and sun directions, each checked as above.
struct CheckedView {
  glm::dvec3 camera, view_dir, sun_dir;
};
inline CheckedView checkedView(const glm::dvec3& camera, const glm::dvec3& view_dir, const glm::dvec3& sun_dir) {
  return {lookupPosition(camera, "camera"), lookupDirection(view_dir, "view direction"),
          lookupDirection(sun_dir, "sun direction")};
}

// A surface lookup's point, normal and sun direction, each checked as above.
struct CheckedSurface {
  glm::dvec3 point, normal, sun_dir;
};
inline CheckedSurface checkedSurface(const glm::dvec3& point, const glm::dvec3& normal, const glm::dvec3& sun_dir) {
  return {lookupPosition(point, "point"), lookupDirection(normal, "normal"), lookupDirection(sun_dir, "sun direction")};
}

// A shadow length (m) as the lookups take it, or Error(BadInput) for a
// negative or non-finite one.
double lookupShadowLength(double shadow_length_m);

// Error(BadInput) for a moon with a non-finite centre or a negative or
// non-finite radius (radius 0 is no moon).
void requireLookupMoon(const Moon& moon);

// Whether `point` lies inside the moon: a camera there sees the moon's
// dark inside, radiance 0 and transmittance 0, not the sky.
inline bool insideMoon(const glm::dvec3& point, const Moon& moon) {
  return moon.present() && glm::length(point - moon.centre_m) < moon.radius_m;
}

}  // namespace skybake
