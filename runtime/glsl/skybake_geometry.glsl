// skybake GLSL library (README.md gives the files' order): rays in the
// atmosphere's shell, the planet's shadow, the sun disk, a moon and the
// media, with the bake's radii and constants. The media mirror
// runtime/physics/atmosphere_media.h; the shell's geometry itself (clamped cosines,
// distances to spheres, radius and cosine along a ray), the phase functions,
// the sun disk's visible fraction, the planet's shadow and the moon's
// occlusion are kernel files the C++ shares (data_formats/kernel/,
// runtime/kernel/), read before this one, and given the bake's constants
// here.
//
// The C++ computes in double, this in float, whose resolution at a planet's
// radius is about half a metre. The formulas are therefore rearranged so
// that no result is the small difference of two radius-sized numbers: a
// distance to a sphere is written as (radius^2 - r^2) / (sum of two
// positive terms) where the direct form would cancel, and r^2 - R^2 as
// (r - R) (r + R), exact in float for r near R.

float skybakeDistanceToAtmosphereEnd(float r, float mu, bool ray_intersects_ground) {
  return skybakeDistanceToAtmosphereEnd(r, mu, skybake_radii_m.x, skybake_radii_m.y, ray_intersects_ground);
}

// rho: the distance to the horizon from radius r, m.
float skybakeDistanceToHorizon(float r) { return skybakeDistanceToHorizon(r, skybake_radii_m.x); }

// The same radius kept in the shell, as every lookup along a ray takes it.
float skybakeShellRadiusAlongRay(float r, float mu, float d) {
  return clamp(skybakeRadiusAlongRay(r, mu, d), skybake_radii_m.x, skybake_radii_m.y);
}

// A ray in the shell with the bake's radii (the kernel
// runtime/kernel/atmosphere_entry.glsl, read before this file).
SkybakeRay skybakeEnterAtmosphere(vec3 start, vec3 dir) {
  return skybakeEnterAtmosphere(skybake_radii_m.x, skybake_radii_m.y, start, dir);
}

// Where the ray (r, mu) with the sun at (mu_s, nu) crosses the edge of the
// planet's shadow over (0, length_m) (the kernel
// runtime/kernel/planet_shadow.glsl with the bake's radius).
SkybakeShadowCrossings skybakePlanetShadowCrossings(float r, float mu, float mu_s, float nu, float length_m) {
  return skybakePlanetShadowCrossings(r, mu, mu_s, nu, skybake_radii_m.x, length_m);
}

// Whether the unit view direction lies within the sun disk: the chord
// |view - sun| against the disk edge's, which float resolves where the
// cosine 0.99999 of a small disk would not.
bool skybakeInSunDisk(vec3 view_dir, vec3 sun_dir) {
  vec3 chord = view_dir - sun_dir;
  return dot(chord, chord) < skybake_sun_disk.y;
}

// ---- a moon before the sun (runtime/physics/moon_occluder.h) ----

// A sphere: centre in metres from the planet's centre (the frame of
// cameras), radius in metres; radius 0: no moon, nothing hidden.
struct SkybakeMoon {
  vec3 centre_m;
  float radius_m;
};

SkybakeMoon skybakeNoMoon() { return SkybakeMoon(vec3(0.0), 0.0); }

// Fraction of the sun disk (unit sun_dir, angular radius sun_radius_rad)
// that `point_m` sees past the moon (the kernel
// runtime/kernel/moon_occlusion.glsl).
float skybakeMoonVisibleSunFraction(SkybakeMoon moon, vec3 point_m, vec3 sun_dir, float sun_radius_rad) {
  return skybakeMoonVisibleSunFraction(moon.centre_m, moon.radius_m, point_m, sun_dir, sun_radius_rad);
}

// Whether the unit view direction from `camera_m` lies within the sun disk
// and outside the moon's disk seen from there.
bool skybakeInSunDiskPastMoon(vec3 camera_m, vec3 view_dir, vec3 sun_dir, SkybakeMoon moon) {
  if (!skybakeInSunDisk(view_dir, sun_dir)) return false;
  if (!(moon.radius_m > 0.0)) return true;
  vec3 to_moon = moon.centre_m - camera_m;
  float distance_m = length(to_moon);
  if (!(distance_m > moon.radius_m)) return false;
  return skybakeAngleBetween(to_moon, view_dir) >= asin(moon.radius_m / distance_m);
}

// A moon seen along a view ray origin_m + t dir (MoonAlongRay), for the
// integrals that walk the ray by distance.
struct SkybakeMoonAlongRay {
  SkybakeMoon moon;
  vec3 origin_m;
  vec3 dir;
  vec3 sun_dir;
};

float skybakeMoonVisibleSunFractionAt(SkybakeMoonAlongRay along, float t) {
  return skybakeMoonVisibleSunFraction(along.moon, along.origin_m + along.dir * t, along.sun_dir, skybake_sun_disk.x);
}

// The Mie phase of the bake's g (the phase functions are the kernel
// runtime/kernel/phase_functions.glsl).
float skybakeMiePhase(float nu) { return skybakeCornetteShanksPhase(skybake_phase.x, skybake_phase.z, nu); }

// Density in [0, 1] of profile 0 (Rayleigh), 1 (Mie) or 2 (absorption) at
// an altitude (runtime/physics/density_profile.h).
float skybakeLayerDensity(int layer, float altitude_m) {
  vec4 shape = skybake_layer_shape[layer];
  return skybakeLayerDensity(shape.y, shape.z, shape.w, skybake_layer_constant[layer].x, altitude_m);
}

float skybakeProfileDensity(int profile, float altitude_m) {
  int count = skybake_profile_layers[profile];
  float layer_bottom_m = 0.0;
  for (int i = 0; i < SKYBAKE_MAX_DENSITY_LAYERS; ++i) {
    if (i >= count) break;
    int layer = profile * SKYBAKE_MAX_DENSITY_LAYERS + i;
    float layer_top_m = layer_bottom_m + skybake_layer_shape[layer].x;
    if (i + 1 == count || altitude_m < layer_top_m) return skybakeLayerDensity(layer, altitude_m);
    layer_bottom_m = layer_top_m;
  }
  return 0.0;
}

float skybakeRayleighDensity(float altitude_m) { return skybakeProfileDensity(0, altitude_m); }
float skybakeMieDensity(float altitude_m) { return skybakeProfileDensity(1, altitude_m); }

// Extinction coefficient per channel, m^-1.
vec4 skybakeExtinctionOfDensities(float rayleigh_density, float mie_density, float absorption_density) {
  return skybake_rayleigh_scattering * rayleigh_density + skybake_mie_extinction * mie_density +
         skybake_absorption_extinction * absorption_density;
}

vec4 skybakeExtinction(float altitude_m) {
  return skybakeExtinctionOfDensities(skybakeRayleighDensity(altitude_m), skybakeMieDensity(altitude_m),
                                      skybakeProfileDensity(2, altitude_m));
}

float skybakeLargestChannel(vec4 s) { return max(max(s.x, s.y), max(s.z, s.w)); }
