// Distances from a point at radius r (metres from the planet centre) along a
// direction whose cosine with the local zenith is mu, to the spheres that
// bound the atmosphere. The texture parameterization is built on these.
#pragma once

#include <algorithm>
#include <cmath>

namespace skybake {

// Cosines drift past +-1 by rounding; acos and sqrt(1 - mu^2) need them inside.
inline double clampCosine(double mu) { return std::clamp(mu, -1.0, 1.0); }

// sqrt of a quantity that is >= 0 in exact arithmetic but may round to a tiny
// negative value (tangent rays, points exactly on a boundary).
inline double safeSqrt(double a) { return std::sqrt(std::max(a, 0.0)); }

// Distance to the sphere of radius `radius` enclosing the point (r <= radius).
inline double distanceToOuterSphere(double r, double mu, double radius) {
  const double discriminant = r * r * (mu * mu - 1.0) + radius * radius;
  return std::max(-r * mu + safeSqrt(discriminant), 0.0);
}

// Distance to the nearer intersection with a sphere below the point (r >=
// radius); only meaningful when rayIntersectsSphere(r, mu, radius).
inline double distanceToInnerSphere(double r, double mu, double radius) {
  const double discriminant = r * r * (mu * mu - 1.0) + radius * radius;
  return std::max(-r * mu - safeSqrt(discriminant), 0.0);
}

// Length of the ray (r, mu) inside the atmosphere: to the ground when it
// hits it, else to the top.
inline double distanceToAtmosphereEnd(double r, double mu, double bottom_radius, double top_radius,
                                      bool ray_intersects_ground) {
  return ray_intersects_ground ? distanceToInnerSphere(r, mu, bottom_radius) : distanceToOuterSphere(r, mu, top_radius);
}

// True when the ray (r, mu) from r >= radius hits the sphere of radius `radius`.
inline bool rayIntersectsSphere(double r, double mu, double radius) {
  return mu < 0.0 && r * r * (mu * mu - 1.0) + radius * radius >= 0.0;
}

// Zenith cosine of the rays from r >= radius tangent to the sphere of radius
// `radius` (the horizon, for the ground's sphere): -sqrt(1 - (radius / r)^2).
inline double tangentZenithCosine(double r, double radius) {
  const double sin_tangent = radius / r;
  return -safeSqrt(1.0 - sin_tangent * sin_tangent);
}

// Radius and zenith cosine at distance d along the ray (r, mu).
inline double radiusAlongRay(double r, double mu, double d) {
  return std::sqrt(std::max(d * d + 2.0 * r * mu * d + r * r, 0.0));
}
inline double cosineAlongRay(double r, double mu, double d, double r_d) {
  return r_d > 0.0 ? clampCosine((r * mu + d) / r_d) : 1.0;
}

}  // namespace skybake
