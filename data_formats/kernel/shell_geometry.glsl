// Kernel (kernel_language.h): distances from a point at radius r (m from
// the planet's centre) along a direction of zenith cosine mu to the spheres
// that bound the atmosphere. The texture parameterization, the bake and
// every lookup, on the CPU and in the shaders, are built on these.
//
// The shaders compute in float, whose resolution at a planet's radius is
// about half a metre, so no result is the small difference of two
// radius-sized numbers: r^2 - R^2 is written (r - R)(r + R), exact for r
// near R, and a distance that the direct form would get by cancellation is
// written (R^2 - r^2) / (sum of two positive terms). In double the same
// forms are as accurate as the direct ones or more.

// Cosines drift past +-1 by rounding; acos and sqrt(1 - mu^2) need them
// inside.
SKYBAKE_KERNEL Real skybakeClampCosine(Real mu) { return clamp(mu, -1.0, 1.0); }

// sqrt of a quantity that is >= 0 in exact arithmetic but may round to a
// tiny negative value (tangent rays, points exactly on a boundary).
SKYBAKE_KERNEL Real skybakeSafeSqrt(Real a) { return sqrt(max(a, 0.0)); }

// Distance to the sphere of radius `radius` >= r that encloses the point.
// Both cases are computed and one selected, so that loops over many rays
// vectorize.
SKYBAKE_KERNEL Real skybakeDistanceToOuterSphere(Real r, Real mu, Real radius) {
  Real q = (radius - r) * (radius + r);
  Real rmu = r * mu;
  Real root = skybakeSafeSqrt(rmu * rmu + q);
  Real denominator = rmu + root;
  Real outward = denominator > 0.0 ? max(q / denominator, 0.0) : 0.0;
  return mu < 0.0 ? max(root - rmu, 0.0) : outward;
}

// True when the ray (r, mu) from r >= radius hits the sphere of radius
// `radius`.
SKYBAKE_KERNEL bool skybakeRayIntersectsSphere(Real r, Real mu, Real radius) {
  Real rmu = r * mu;
  return mu < 0.0 && rmu * rmu - (r - radius) * (r + radius) >= 0.0;
}

// Distance to the nearer intersection with a sphere below the point (r >=
// radius); meaningful where skybakeRayIntersectsSphere, 0 elsewhere.
SKYBAKE_KERNEL Real skybakeDistanceToInnerSphere(Real r, Real mu, Real radius) {
  Real q = (r - radius) * (r + radius);
  Real rmu = r * mu;
  Real denominator = skybakeSafeSqrt(rmu * rmu - q) - rmu;
  return mu < 0.0 && denominator > 0.0 ? max(q / denominator, 0.0) : 0.0;
}

// Length of the ray (r, mu) inside the atmosphere: to the ground when it
// hits it, else to the top.
SKYBAKE_KERNEL Real skybakeDistanceToAtmosphereEnd(Real r, Real mu, Real bottom_radius, Real top_radius,
                                                   bool ray_intersects_ground) {
  return ray_intersects_ground ? skybakeDistanceToInnerSphere(r, mu, bottom_radius)
                               : skybakeDistanceToOuterSphere(r, mu, top_radius);
}

// The distance from r >= radius to the horizon of the sphere of radius
// `radius`, along the ray tangent to it (rho, for the ground's sphere).
SKYBAKE_KERNEL Real skybakeDistanceToHorizon(Real r, Real radius) {
  return skybakeSafeSqrt((r - radius) * (r + radius));
}

// Zenith cosine of the rays from r >= radius tangent to the sphere of
// radius `radius` (the horizon, for the ground's sphere):
// -sqrt(1 - (radius / r)^2).
SKYBAKE_KERNEL Real skybakeTangentZenithCosine(Real r, Real radius) {
  return -skybakeDistanceToHorizon(r, radius) / r;
}

// Radius and zenith cosine at distance d along the ray (r, mu).
SKYBAKE_KERNEL Real skybakeRadiusAlongRay(Real r, Real mu, Real d) {
  return sqrt(max(d * (d + 2.0 * r * mu) + r * r, 0.0));
}
SKYBAKE_KERNEL Real skybakeCosineAlongRay(Real r, Real mu, Real d, Real r_d) {
  return r_d > 0.0 ? skybakeClampCosine((r * mu + d) / r_d) : 1.0;
}
