// Kernel (data_formats/kernel/kernel_language.h): where a ray crosses the
// edge of the planet's shadow. For a point sun the shadow is the
// half-infinite cylinder of the planet's radius behind the planet, away
// from the sun. Light scattered once along a ray switches on or off there,
// a jump that a quadrature rule spanning it integrates badly: at twilight a
// grazing ray is sunlit only over a short, high stretch, and a rule that
// straddles the jump is tens of percent off. Integrators (the bake, the
// reference solver, the lookups' twilight integrals on the CPU and in the
// shaders) split their rays at these distances.

// The crossings in (0, length): count of them, and their distances (m),
// ascending, in distance_m.x and .y.
struct SkybakeShadowCrossings {
  int count;
  Real2 distance_m;
};

// The crossings of the segment origin + t dir, t in (0, length_m), with
// the cylinder's surface: the roots of qa t^2 + qb t + qc = 0 that lie
// behind the planet, origin_along + t dir_along < 0 (the components of the
// origin and the direction along the unit vector toward the sun).
SKYBAKE_KERNEL SkybakeShadowCrossings skybakeShadowCylinderCrossings(Real qa, Real qb, Real qc, Real origin_along,
                                                                     Real dir_along, Real length_m) {
  SkybakeShadowCrossings crossings;
  crossings.count = 0;
  crossings.distance_m = Real2(0.0, 0.0);
  Real discriminant = qb * qb - 4.0 * qa * qc;
  if (!(qa > 0.0) || !(discriminant > 0.0)) return crossings;
  Real root = sqrt(discriminant);
  // The two roots without cancellation: q / qa and qc / q.
  Real q = -0.5 * (qb + (qb < 0.0 ? -root : root));
  Real t0 = q / qa;
  Real t1 = q != 0.0 ? qc / q : t0;
  Real near_t = min(t0, t1);
  Real far_t = max(t0, t1);
  if (near_t > 0.0 && near_t < length_m && origin_along + near_t * dir_along < 0.0) {
    crossings.distance_m.x = near_t;
    crossings.count = 1;
  }
  if (far_t > 0.0 && far_t < length_m && origin_along + far_t * dir_along < 0.0) {
    if (crossings.count == 0)
      crossings.distance_m.x = far_t;
    else
      crossings.distance_m.y = far_t;
    crossings.count += 1;
  }
  return crossings;
}

// The crossings of the segment origin + t dir, t in (0, length_m); `sun`
// the unit vector toward the sun, positions from the planet's centre. The
// squared distance from the axis, |p - (p.s) s|^2 = R^2, is the quadratic.
SKYBAKE_KERNEL SkybakeShadowCrossings skybakePlanetShadowCrossingsOfSegment(Real3 origin, Real3 dir, Real3 sun,
                                                                            Real bottom_radius_m, Real length_m) {
  Real origin_along = dot(origin, sun);
  Real dir_along = dot(dir, sun);
  Real3 origin_across = origin - sun * origin_along;
  Real3 dir_across = dir - sun * dir_along;
  return skybakeShadowCylinderCrossings(dot(dir_across, dir_across), 2.0 * dot(origin_across, dir_across),
                                        dot(origin_across, origin_across) - bottom_radius_m * bottom_radius_m,
                                        origin_along, dir_along, length_m);
}

// The same for the ray from radius r at zenith cosine mu, the sun at zenith
// cosine mu_s making cosine nu with it (a nu the two zenith angles do not
// allow is taken at its nearest possible value), over (0, length_m); the
// ray is put in the x-z plane above the +z pole.
SKYBAKE_KERNEL SkybakeShadowCrossings skybakePlanetShadowCrossings(Real r, Real mu, Real mu_s, Real nu,
                                                                   Real bottom_radius_m, Real length_m) {
  Real view_sin = skybakeSafeSqrt(1.0 - mu * mu);
  Real sun_sin = skybakeSafeSqrt(1.0 - mu_s * mu_s);
  Real sun_x = view_sin > 0.0 ? clamp((nu - mu * mu_s) / view_sin, -sun_sin, sun_sin) : sun_sin;
  Real3 sun = Real3(sun_x, skybakeSafeSqrt(sun_sin * sun_sin - sun_x * sun_x), mu_s);
  Real3 dir = Real3(view_sin, 0.0, mu);
  Real origin_along = r * mu_s;
  Real dir_along = dot(dir, sun);
  Real3 origin_across = Real3(0.0, 0.0, r) - sun * origin_along;
  Real3 dir_across = dir - sun * dir_along;
  // |origin_across|^2 - R^2 = (r sin - R)(r sin + R), with r sin - R
  // written (r - R) - r mu_s^2 / (1 + sin): the shadow's edge passes near
  // the point exactly where these nearly cancel.
  Real qc = ((r - bottom_radius_m) - r * mu_s * mu_s / (1.0 + sun_sin)) * (r * sun_sin + bottom_radius_m);
  return skybakeShadowCylinderCrossings(dot(dir_across, dir_across), 2.0 * dot(origin_across, dir_across), qc,
                                        origin_along, dir_along, length_m);
}
