// Kernel (data_formats/kernel/kernel_language.h): how much of the sun disk
// a point sees above the planet's horizon. The bake, the runtime, the
// shaders and the reference solver all count the sun this way: the light
// arriving from the disk's centre, times this fraction (and, on a surface,
// times the cosine of the centre's direction). So the validation measures
// the bake's numerical error, not a difference between two models of the
// sun.

// Fraction of the sun disk above the horizon given how far (in cosine) its
// centre is above it and the disk's half-size in the same units: a smooth
// ramp over the disk's diameter, within 0.04 of the disk's exact area above
// a straight horizon, with no kink in the sky's derivative. A point sun
// (half_size 0) is all up or all down. Both cases are computed and one
// selected, so that loops over many suns vectorize.
SKYBAKE_KERNEL Real skybakeSunDiskVisibleFraction(Real height, Real half_size) {
  Real ramp = clamp((height + half_size) / (2.0 * half_size), 0.0, 1.0);
  Real point = height > 0.0 ? 1.0 : 0.0;
  Real t = half_size > 0.0 ? ramp : point;
  return t * t * (3.0 - 2.0 * t);
}

// The disk's half-size in zenith cosine near the horizon seen from radius
// r_m: its angular radius times the sine of the horizon's zenith angle,
// bottom_radius_m / r_m.
SKYBAKE_KERNEL Real skybakeSunDiskHalfSizeAtHorizon(Real bottom_radius_m, Real r_m, Real sun_angular_radius_rad) {
  return bottom_radius_m / r_m * sun_angular_radius_rad;
}
