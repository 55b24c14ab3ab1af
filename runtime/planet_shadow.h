// Where a ray crosses the edge of the planet's shadow. For a point sun the
// shadow is the half-infinite cylinder of the planet's radius behind the
// planet, away from the sun. Light scattered once along a ray switches on or
// off there, a jump that a quadrature rule spanning it integrates badly: at
// twilight a grazing ray is sunlit only over a short, high stretch, and a
// rule that straddles the jump is tens of percent off. Integrators split
// their rays at these distances.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace skybake {

struct ShadowCrossings {
  int count = 0;
  std::array<double, 2> distance{};  // ascending, each in (0, length)
};

// Crossings of the shadow's edge by the segment origin + t dir, t in
// (0, length); `sun` is the unit vector toward the sun, positions are
// relative to the planet's centre.
inline ShadowCrossings planetShadowCrossings(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& sun,
                                             double bottom_radius, double length) {
  ShadowCrossings out;
  // Distance to the axis: |p - (p.s) s|^2 = R^2, a quadratic in t.
  const double origin_along = glm::dot(origin, sun), dir_along = glm::dot(dir, sun);
  const glm::dvec3 origin_across = origin - sun * origin_along, dir_across = dir - sun * dir_along;
  const double qa = glm::dot(dir_across, dir_across);
  const double qb = 2.0 * glm::dot(origin_across, dir_across);
  const double qc = glm::dot(origin_across, origin_across) - bottom_radius * bottom_radius;
  const double discriminant = qb * qb - 4.0 * qa * qc;
  if (!(qa > 0.0) || !(discriminant > 0.0)) return out;
  const double root = std::sqrt(discriminant);
  for (double t : {(-qb - root) / (2.0 * qa), (-qb + root) / (2.0 * qa)}) {
    // Only the cylinder's half behind the planet casts the shadow.
    const bool behind_planet = origin_along + t * dir_along < 0.0;
    if (t > 0.0 && t < length && behind_planet) out.distance[out.count++] = t;
  }
  return out;
}

// The same for the ray from radius r at zenith cosine mu, the sun at zenith
// cosine mu_s making cosine nu with it (a nu the two zenith angles do not
// allow is taken at its nearest possible value), over (0, length). The ray
// is put in the x-z plane above the +z pole.
inline ShadowCrossings planetShadowCrossings(double r, double mu, double mu_s, double nu, double bottom_radius,
                                             double length) {
  const double view_sin = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  const double sun_sin = std::sqrt(std::max(0.0, 1.0 - mu_s * mu_s));
  const double sun_x = view_sin > 0.0 ? std::clamp((nu - mu * mu_s) / view_sin, -sun_sin, sun_sin) : sun_sin;
  const glm::dvec3 sun(sun_x, std::sqrt(std::max(0.0, sun_sin * sun_sin - sun_x * sun_x)), mu_s);
  return planetShadowCrossings(glm::dvec3(0.0, 0.0, r), glm::dvec3(view_sin, 0.0, mu), sun, bottom_radius, length);
}

}  // namespace skybake
