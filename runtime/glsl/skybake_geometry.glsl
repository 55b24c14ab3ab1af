// skybake GLSL library (README.md gives the files' order): rays in the
// atmosphere's shell, the planet's shadow, the sun disk, a moon and the
// media, with the bake's radii and constants. Mirrors
// runtime/atmosphere_ray.h, planet_shadow.h, moon_occluder.h and
// atmosphere_media.h; the shell's geometry itself (clamped cosines,
// distances to spheres, radius and cosine along a ray), the phase functions
// and the sun disk's visible fraction are kernel files the C++ shares
// (data_formats/kernel/, runtime/kernel/), read before this one.
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
float skybakeDistanceToHorizon(float r) {
  float bottom = skybake_radii_m.x;
  return skybakeSafeSqrt((r - bottom) * (r + bottom));
}

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
// planet's shadow over (0, length_m): runtime/planet_shadow.h, with the ray
// in the x-z plane above the +z pole. Distances ascending.
struct SkybakeShadowCrossings {
  int count;
  vec2 distance_m;
};

SkybakeShadowCrossings skybakePlanetShadowCrossings(float r, float mu, float mu_s, float nu, float length_m) {
  SkybakeShadowCrossings out_crossings = SkybakeShadowCrossings(0, vec2(0.0));
  float bottom = skybake_radii_m.x;
  float view_sin = skybakeSafeSqrt(1.0 - mu * mu);
  float sun_sin = skybakeSafeSqrt(1.0 - mu_s * mu_s);
  float sun_x = view_sin > 0.0 ? clamp((nu - mu * mu_s) / view_sin, -sun_sin, sun_sin) : sun_sin;
  vec3 sun = vec3(sun_x, skybakeSafeSqrt(sun_sin * sun_sin - sun_x * sun_x), mu_s);
  vec3 dir = vec3(view_sin, 0.0, mu);
  float origin_along = r * mu_s;
  float dir_along = dot(dir, sun);
  vec3 origin_across = vec3(0.0, 0.0, r) - sun * origin_along;
  vec3 dir_across = dir - sun * dir_along;
  float qa = dot(dir_across, dir_across);
  float qb = 2.0 * dot(origin_across, dir_across);
  // |origin_across|^2 - R^2 = (r sin - R)(r sin + R), and r sin - R written
  // as (r - R) - r mu_s^2 / (1 + sin): the shadow's edge passes near the
  // camera exactly when these nearly cancel.
  float qc = ((r - bottom) - r * mu_s * mu_s / (1.0 + sun_sin)) * (r * sun_sin + bottom);
  float discriminant = qb * qb - 4.0 * qa * qc;
  if (!(qa > 0.0) || !(discriminant > 0.0)) return out_crossings;
  float root = sqrt(discriminant);
  // The two roots without cancellation: q / qa and qc / q.
  float q = -0.5 * (qb + (qb < 0.0 ? -root : root));
  float t0 = q / qa;
  float t1 = q != 0.0 ? qc / q : t0;
  vec2 roots = vec2(min(t0, t1), max(t0, t1));
  for (int i = 0; i < 2; ++i) {
    float t = roots[i];
    // Only the cylinder's half behind the planet casts the shadow.
    bool behind_planet = origin_along + t * dir_along < 0.0;
    if (t > 0.0 && t < length_m && behind_planet) {
      if (out_crossings.count == 0)
        out_crossings.distance_m.x = t;
      else
        out_crossings.distance_m.y = t;
      out_crossings.count += 1;
    }
  }
  return out_crossings;
}

// Whether the unit view direction lies within the sun disk: the chord
// |view - sun| against the disk edge's, which float resolves where the
// cosine 0.99999 of a small disk would not.
bool skybakeInSunDisk(vec3 view_dir, vec3 sun_dir) {
  vec3 chord = view_dir - sun_dir;
  return dot(chord, chord) < skybake_sun_disk.y;
}

// ---- a moon before the sun (runtime/moon_occluder.h) ----

// A sphere: centre in metres from the planet's centre (the frame of
// cameras), radius in metres; radius 0: no moon, nothing hidden.
struct SkybakeMoon {
  vec3 centre_m;
  float radius_m;
};

SkybakeMoon skybakeNoMoon() { return SkybakeMoon(vec3(0.0), 0.0); }

// Area of the intersection of two discs of radii a and b whose centres are
// `separation` apart (discOverlapArea: the exact circle-circle lens; the
// inverse cosines' arguments clamped against rounding near tangency).
float skybakeDiscOverlapArea(float a, float b, float separation) {
  if (!(a > 0.0) || !(b > 0.0) || separation >= a + b) return 0.0;
  float small = min(a, b);
  if (separation <= abs(a - b)) return SKYBAKE_PI * small * small;
  float d = separation;
  float angle_a = acos(clamp((d * d + a * a - b * b) / (2.0 * d * a), -1.0, 1.0));
  float angle_b = acos(clamp((d * d + b * b - a * a) / (2.0 * d * b), -1.0, 1.0));
  float kite = max((-d + a + b) * (d + a - b) * (d - a + b) * (d + a + b), 0.0);
  return max(a * a * angle_a + b * b * angle_b - 0.5 * sqrt(kite), 0.0);
}

// Fraction of a sun disk of angular radius sun_radius_rad not covered by a
// moon disk of angular radius moon_radius_rad whose centre is separation_rad
// from the sun's (sunFractionPastMoonDisc; both discs flat).
float skybakeSunFractionPastMoonDisc(float sun_radius_rad, float moon_radius_rad, float separation_rad) {
  if (!(moon_radius_rad > 0.0)) return 1.0;
  if (!(sun_radius_rad > 0.0)) return separation_rad < moon_radius_rad ? 0.0 : 1.0;
  float covered = skybakeDiscOverlapArea(sun_radius_rad, moon_radius_rad, separation_rad) /
                  (SKYBAKE_PI * sun_radius_rad * sun_radius_rad);
  return clamp(1.0 - covered, 0.0, 1.0);
}

// Fraction of the sun disk (unit sun_dir, angular radius sun_radius_rad)
// that `point_m` sees past the moon (Moon::visibleSunFraction): the moon's
// direction and angular radius seen from the point, so with its parallax;
// the separation from atan of the cross and dot products, precise at the
// small angles of an umbra's edge. A point inside the moon sees nothing.
float skybakeMoonVisibleSunFraction(SkybakeMoon moon, vec3 point_m, vec3 sun_dir, float sun_radius_rad) {
  if (!(moon.radius_m > 0.0)) return 1.0;
  vec3 to_moon = moon.centre_m - point_m;
  float distance_m = length(to_moon);
  if (!(distance_m > moon.radius_m)) return 0.0;
  float moon_radius_rad = asin(moon.radius_m / distance_m);
  float separation_rad = atan(length(cross(to_moon, sun_dir)), dot(to_moon, sun_dir));
  return skybakeSunFractionPastMoonDisc(sun_radius_rad, moon_radius_rad, separation_rad);
}

// Whether the unit view direction from `camera_m` lies within the sun disk
// and outside the moon's disk seen from there.
bool skybakeInSunDiskPastMoon(vec3 camera_m, vec3 view_dir, vec3 sun_dir, SkybakeMoon moon) {
  if (!skybakeInSunDisk(view_dir, sun_dir)) return false;
  if (!(moon.radius_m > 0.0)) return true;
  vec3 to_moon = moon.centre_m - camera_m;
  float distance_m = length(to_moon);
  if (!(distance_m > moon.radius_m)) return false;
  return atan(length(cross(to_moon, view_dir)), dot(to_moon, view_dir)) >= asin(moon.radius_m / distance_m);
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
// an altitude (runtime/density_profile.h).
float skybakeLayerDensity(int layer, float altitude_m) {
  vec4 shape = skybake_layer_shape[layer];
  float value = shape.y * exp(shape.z * altitude_m) + shape.w * altitude_m + skybake_layer_constant[layer].x;
  return clamp(value, 0.0, 1.0);
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
