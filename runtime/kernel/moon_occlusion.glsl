// Kernel (data_formats/kernel/kernel_language.h): how much of the sun disk
// a moon hides. Seen from a point, a near moon covers part of the disk: how
// much depends on the point (the moon's direction and angular radius change
// across the planet by a degree and a few percent), which is what confines
// totality to a narrow umbra. The runtime's eclipse lookups, the reference
// solver, skybake render and the shaders all count it so.

// Area of the intersection of two discs of radii a and b whose centres are
// `separation` apart (same units; the exact circle-circle lens). The
// inverse cosines' arguments are clamped: rounding near tangency would
// otherwise give NaN.
SKYBAKE_KERNEL Real skybakeDiscOverlapArea(Real a, Real b, Real separation) {
  if (!(a > 0.0) || !(b > 0.0) || separation >= a + b) return 0.0;
  Real small_radius = min(a, b);
  if (separation <= abs(a - b)) return SKYBAKE_PI * small_radius * small_radius;
  Real d = separation;
  Real angle_a = acos(clamp((d * d + a * a - b * b) / (2.0 * d * a), -1.0, 1.0));
  Real angle_b = acos(clamp((d * d + b * b - a * a) / (2.0 * d * b), -1.0, 1.0));
  Real kite = max((-d + a + b) * (d + a - b) * (d - a + b) * (d + a + b), 0.0);
  return max(a * a * angle_a + b * b * angle_b - 0.5 * sqrt(kite), 0.0);
}

// Fraction of a sun disk of angular radius sun_radius_rad not covered by a
// moon disk of angular radius moon_radius_rad whose centre is
// separation_rad from the sun's: 1 with no overlap, 1 - (moon / sun)^2 at
// the centre of an annular eclipse, 0 in totality. Both discs are taken as
// flat, which for the sun's 0.27 deg is off by its angular radius squared
// (2e-5 relative). A point sun (radius 0) is all covered or all free.
SKYBAKE_KERNEL Real skybakeSunFractionPastMoonDisc(Real sun_radius_rad, Real moon_radius_rad, Real separation_rad) {
  if (!(moon_radius_rad > 0.0)) return 1.0;
  if (!(sun_radius_rad > 0.0)) return separation_rad < moon_radius_rad ? 0.0 : 1.0;
  Real covered = skybakeDiscOverlapArea(sun_radius_rad, moon_radius_rad, separation_rad) /
                 (SKYBAKE_PI * sun_radius_rad * sun_radius_rad);
  return clamp(1.0 - covered, 0.0, 1.0);
}

// The angle (rad) between two directions: atan of the cross and dot
// products, precise at the small angles an eclipse and the sun disk are
// made of (an inverse cosine of their dot product loses half its digits
// there, all of them below 1e-4 rad in float).
SKYBAKE_KERNEL Real skybakeAngleBetween(Real3 a, Real3 b) { return atan(length(cross(a, b)), dot(a, b)); }

// Fraction of the sun disk (unit sun_dir, the sun being far; angular radius
// sun_radius_rad) that point_m sees past a moon of radius moon_radius_m
// centred at moon_centre_m (all m from the planet's centre): the moon's
// direction and angular radius as seen from the point, so with its
// parallax. A point inside the moon sees nothing; radius 0 is no moon.
SKYBAKE_KERNEL Real skybakeMoonVisibleSunFraction(Real3 moon_centre_m, Real moon_radius_m, Real3 point_m,
                                                  Real3 sun_dir, Real sun_radius_rad) {
  if (!(moon_radius_m > 0.0)) return 1.0;
  Real3 to_moon = moon_centre_m - point_m;
  Real distance_m = length(to_moon);
  if (!(distance_m > moon_radius_m)) return 0.0;
  return skybakeSunFractionPastMoonDisc(sun_radius_rad, asin(moon_radius_m / distance_m),
                                        skybakeAngleBetween(to_moon, sun_dir));
}
