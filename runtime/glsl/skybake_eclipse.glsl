// skybake GLSL library (README.md gives the files' order): the lookups during a solar eclipse
// (runtime/sky_eclipse.cpp, eclipse_skylight.cpp; docs/ECLIPSES.md), the
// same model as the C++: single scattering is the plain lookup's scaled by
// the ratio of the ray's single-scattering integrals with and without the
// moon; multiple scattering and the sky's irradiance are scaled by F, the
// sun's visible fraction averaged over where the light reaching the air
// around a point was scattered (skybakeEclipseSkylight). The moon's occlusion
// is skybakeMoonVisibleSunFraction (skybake_geometry.glsl).

// A program without eclipses may define SKYBAKE_NO_ECLIPSE_LOOKUPS and is
// spared compiling these (see SKYBAKE_NO_RADIANCE_TO_POINT in skybake_sky.glsl).
#ifndef SKYBAKE_NO_ECLIPSE_LOOKUPS

// Whether the moon may hide part of the sun from some point of the
// atmosphere within reach of a ray from `point_m` (Sky::moonHidesSunNear);
// false: the eclipse lookups give the plain ones.
bool skybakeMoonHidesSunNear(vec3 point_m, vec3 sun_dir, SkybakeMoon moon) {
  if (!(moon.radius_m > 0.0)) return false;
  vec3 to_moon = moon.centre_m - point_m;
  float distance_m = length(to_moon);
  float bottom = skybake_radii_m.x;
  float top = skybake_radii_m.y;
  // Anywhere in the atmosphere lies within this of the point, and the moon
  // is seen from there displaced by at most this over its distance.
  float reach_m = 2.0 * sqrt((top - bottom) * (top + bottom)) + (length(point_m) - bottom);
  if (!(distance_m > reach_m + moon.radius_m)) return true;
  float parallax_rad = reach_m / (distance_m - reach_m);
  float moon_radius_rad = asin(min(moon.radius_m / (distance_m - reach_m), 1.0));
  float separation_rad = atan(length(cross(to_moon, sun_dir)), dot(to_moon, sun_dir));
  return separation_rad < skybake_sun_disk.x + moon_radius_rad + parallax_rad;
}

// F per channel for the neighbourhood of `point_m` (eclipseSkylightFraction,
// the kernel's quadrature of runtime/physics/eclipse_skylight.h): the visible
// fraction averaged over directions and distances, weighted by the
// scattering there and an optical depth back to the point that counts
// absorption and the share 1 - SKYBAKE_ECLIPSE_REDIRECTED_SCATTERING_SHARE
// of scattering. 4096 points: a renderer computes it once per camera (it is
// the same for every view ray that starts there).
vec4 skybakeEclipseSkylightFraction(vec3 point_m, vec3 sun_dir, SkybakeMoon moon) {
  if (!(moon.radius_m > 0.0)) return vec4(1.0);
  float bottom = skybake_radii_m.x;
  float top = skybake_radii_m.y;
  float alpha = skybake_sun_disk.x;
  float len = length(point_m);
  float r = clamp(len, bottom, top);
  vec3 up = len > 0.0 ? point_m / len : vec3(0.0, 0.0, 1.0);
  vec3 x = up * r;
  vec3 helper = abs(up.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 east = normalize(cross(helper, up));
  vec3 north = cross(up, east);
  vec4 lit = vec4(0.0);
  vec4 all_weight = vec4(0.0);
  // Zenith cosines dense near the horizon's h: mu = h + (1 -+ h) u |u|.
  float horizon_mu = skybakeTangentZenithCosine(r, bottom);
  int elevations = SKYBAKE_ECLIPSE_KERNEL_ELEVATIONS;
  int azimuths = SKYBAKE_ECLIPSE_KERNEL_AZIMUTHS;
  int distances = SKYBAKE_ECLIPSE_KERNEL_DISTANCES;
  float first_m = SKYBAKE_ECLIPSE_FIRST_DISTANCE_M;
  for (int e = 0; e < elevations; ++e) {
    float u = -1.0 + 2.0 * (float(e) + 0.5) / float(elevations);
    float side = u < 0.0 ? 1.0 + horizon_mu : 1.0 - horizon_mu;
    float mu = horizon_mu + side * u * abs(u);
    float solid_angle = 2.0 * side * abs(u) * (2.0 / float(elevations));
    float sin_theta = skybakeSafeSqrt(1.0 - mu * mu);
    bool ground = skybakeRayIntersectsSphere(r, mu, bottom);
    float end_m = skybakeDistanceToAtmosphereEnd(r, mu, ground);
    // Directions that leave the air within the first step weigh nothing
    // (no continue: llvmpipe mishandles it in loops this deep).
    int azimuth_count = end_m > first_m ? azimuths : 0;
    float growth = pow(max(end_m, first_m) / first_m, 1.0 / float(distances - 1));
    for (int j = 0; j < azimuth_count; ++j) {
      // Each band turned by half a step against the last.
      float phi = 2.0 * SKYBAKE_PI * (float(j) + 0.5 * float(e % 2)) / float(azimuths);
      vec3 w = up * mu + (east * cos(phi) + north * sin(phi)) * sin_theta;
      vec4 depth = vec4(0.0);
      float start = 0.0;
      for (int k = 0; k < distances; ++k) {
        float stop = k + 1 == distances ? end_m : first_m * pow(growth, float(k));
        float mid = 0.5 * (start + stop);
        float step_m = stop - start;
        vec3 p = x + w * mid;
        float altitude_m = max(skybakeRadiusAlongRay(r, mu, mid) - bottom, 0.0);
        // Each density once (llvmpipe counts every pass of their loops).
        float rayleigh_density = skybakeRayleighDensity(altitude_m);
        float mie_density = skybakeMieDensity(altitude_m);
        vec4 scattering = skybake_rayleigh_scattering * rayleigh_density + skybake_mie_scattering * mie_density;
        vec4 extinction =
            skybakeExtinctionOfDensities(rayleigh_density, mie_density, skybakeProfileDensity(2, altitude_m)) -
            scattering * SKYBAKE_ECLIPSE_REDIRECTED_SCATTERING_SHARE;
        vec4 weight = scattering * exp(-(depth + extinction * (0.5 * step_m))) * (step_m * solid_angle);
        depth += extinction * step_m;
        all_weight += weight;
        lit += weight * skybakeMoonVisibleSunFraction(moon, p, sun_dir, alpha);
        start = stop;
      }
    }
  }
  // Per channel, whole-vector operations (no component writes in
  // divergent flow, which llvmpipe miscompiles in shaders this large).
  float here = skybakeMoonVisibleSunFraction(moon, x, sun_dir, alpha);
  bvec4 weighed = greaterThan(all_weight, vec4(0.0));
  vec4 share = mix(vec4(here), clamp(lit / max(all_weight, vec4(1e-37)), 0.0, 1.0), vec4(weighed));
  return share * vec4(lessThan(vec4(0.0, 1.0, 2.0, 3.0), vec4(float(skybake_outputs.z))));
}

// The skylight share F at `point_m` (Sky::eclipseSkylight): exactly 1 where
// the moon hides the sun from nowhere within reach.
vec4 skybakeEclipseSkylight(vec3 point_m, vec3 sun_dir, SkybakeMoon moon) {
  if (!skybakeMoonHidesSunNear(point_m, sun_dir, moon)) return vec4(1.0);
  return skybakeEclipseSkylightFraction(point_m, sun_dir, moon);
}

// eclipsed / plain per channel, clamped to [0, 1]; 0 where the plain value
// is at rounding level.
vec4 skybakeEclipsedShare(vec4 eclipsed, vec4 plain) {
  bvec4 counted = greaterThan(plain, vec4(SKYBAKE_ECLIPSE_SMALLEST_UNECLIPSED_SINGLE));
  return clamp(eclipsed / max(plain, vec4(SKYBAKE_ECLIPSE_SMALLEST_UNECLIPSED_SINGLE)), 0.0, 1.0) * vec4(counted);
}

// Sky radiance under an eclipse, the camera's skylight share given
// (skybakeEclipseSkylight at the ray's start: the camera, or where a ray
// from space enters the atmosphere), as Sky::skyRadiance(..., moon,
// camera_skylight).
SkybakeRadianceAndTransmittance skybakeSkyRadiance(vec3 camera_m, vec3 view_dir, vec3 sun_dir, SkybakeMoon moon,
                                                   vec4 camera_skylight) {
  SkybakeSkyRadianceParts p = skybakeSkyRadianceParts(camera_m, view_dir, sun_dir, 0.0);
  if (!p.inside) return SkybakeRadianceAndTransmittance(vec4(0.0), vec4(1.0));
  if (skybakeMoonHidesSunNear(p.start.origin, sun_dir, moon)) {
    SkybakeRay s = p.start;
    // With the moon and without it, at the same nodes.
    SkybakeMoonAlongRay along = SkybakeMoonAlongRay(moon, s.origin, view_dir, sun_dir);
    SkybakeSingleScatteringPastMoon integral =
        skybakeIntegrateSingleScattering(s.r, s.mu, p.mu_s, p.nu, s.ends_on_ground, p.lit_from_m, s.length_m,
                                         SKYBAKE_ECLIPSE_SINGLE_SCATTERING_SEGMENTS, along);
    SkybakeSingleScattering with_moon = integral.past_moon;
    SkybakeSingleScattering without = integral.plain;
    p.single.rayleigh *= skybakeEclipsedShare(with_moon.rayleigh, without.rayleigh);
    p.single.mie *= skybakeEclipsedShare(with_moon.mie, without.mie);
  }
  return SkybakeRadianceAndTransmittance(skybakeSingleScatteringRadiance(p.single, p.nu) + p.multiple * camera_skylight,
                                         p.transmittance);
}

// Sky radiance under an eclipse (Sky::skyRadiance(..., moon)): the
// skylight share computed at the ray's start. Costly (the share's 4096
// points): where many rays start at one camera, compute the share once
// and call the form above.
SkybakeRadianceAndTransmittance skybakeSkyRadiance(vec3 camera_m, vec3 view_dir, vec3 sun_dir, SkybakeMoon moon) {
  SkybakeRay start = skybakeEnterAtmosphere(camera_m, view_dir);
  if (!start.inside) return SkybakeRadianceAndTransmittance(vec4(0.0), vec4(1.0));
  return skybakeSkyRadiance(camera_m, view_dir, sun_dir, moon, skybakeEclipseSkylight(start.origin, sun_dir, moon));
}

// The share of the plain sky irradiance at `point_m` left under an eclipse
// (Sky::eclipsedSkyIrradianceShare): eclipsed over plain sky radiance, each
// summed over the same cosine-weighted directions.
vec4 skybakeEclipsedSkyIrradianceShare(vec3 point_m, vec3 sun_dir, SkybakeMoon moon) {
  float len = length(point_m);
  vec3 up = len > 0.0 ? point_m / len : vec3(0.0, 0.0, 1.0);
  vec3 from = up * clamp(len, skybake_radii_m.x, skybake_radii_m.y);
  vec3 helper = abs(up.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 east = normalize(cross(helper, up));
  vec3 north = cross(up, east);
  vec4 skylight = skybakeEclipseSkylight(from, sun_dir, moon);
  vec4 eclipsed = vec4(0.0);
  vec4 plain = vec4(0.0);
  for (int b = 0; b < SKYBAKE_ECLIPSE_IRRADIANCE_BANDS; ++b) {
    float sin_squared = (float(b) + 0.5) / float(SKYBAKE_ECLIPSE_IRRADIANCE_BANDS);
    float sin_theta = sqrt(sin_squared);
    float cos_theta = sqrt(1.0 - sin_squared);
    for (int j = 0; j < SKYBAKE_ECLIPSE_IRRADIANCE_AZIMUTHS; ++j) {
      float phi = 2.0 * SKYBAKE_PI * (float(j) + 0.5 * float(b % 2)) / float(SKYBAKE_ECLIPSE_IRRADIANCE_AZIMUTHS);
      vec3 dir = up * cos_theta + (east * cos(phi) + north * sin(phi)) * sin_theta;
      // Without a moon the eclipse lookup is the plain one: one call site.
      // (WebGL refuses ?: between structs: the moon is chosen by an if.)
      for (int i = 0; i < 2; ++i) {
        SkybakeMoon pass_moon = moon;
        if (i != 0) pass_moon = skybakeNoMoon();
        vec4 radiance =
            skybakeSkyRadiance(from, dir, sun_dir, pass_moon, i == 0 ? skylight : vec4(1.0)).radiance;
        if (i == 0)
          eclipsed += radiance;
        else
          plain += radiance;
      }
    }
  }
  return skybakeEclipsedShare(eclipsed, plain);
}

// Sun and sky irradiance under an eclipse (Sky::irradiance(..., moon)): the
// sun's part times the moon's visible fraction at the point, the sky's
// times the eclipsed share of the sky around it.
// The plain irradiance `e` at point_m under the eclipse.
SkybakeSunAndSkyIrradiance skybakeEclipsedIrradiance(SkybakeSunAndSkyIrradiance e, vec3 point_m, vec3 sun_dir,
                                                     SkybakeMoon moon) {
  e.sun *= skybakeMoonVisibleSunFraction(moon, point_m, sun_dir, skybake_sun_disk.x);
  if (skybakeMoonHidesSunNear(point_m, sun_dir, moon)) e.sky *= skybakeEclipsedSkyIrradianceShare(point_m, sun_dir, moon);
  return e;
}

SkybakeSunAndSkyIrradiance skybakeSunAndSkyIrradiance(vec3 point_m, vec3 normal, vec3 sun_dir, SkybakeMoon moon) {
  return skybakeEclipsedIrradiance(skybakeSunAndSkyIrradiance(point_m, normal, sun_dir), point_m, sun_dir, moon);
}

// What a viewer receives under an eclipse, the sun disk aside
// (Sky::receivedRadiance(..., moon, camera_skylight)): the eclipsed sky
// plus, for a ray that ends on the ground, the ground lit by the eclipsed
// sun and sky.
SkybakeRadianceAndTransmittance skybakeReceivedRadiance(vec3 camera_m, vec3 view_dir, vec3 sun_dir, SkybakeMoon moon,
                                                        vec4 camera_skylight) {
  SkybakeRadianceAndTransmittance v = skybakeSkyRadiance(camera_m, view_dir, sun_dir, moon, camera_skylight);
  SkybakeRay start = skybakeEnterAtmosphere(camera_m, view_dir);
  if (!start.inside || !start.ends_on_ground) return v;
  // The plain irradiance as skybakeReceivedRadiance takes it, on the
  // ground's sphere; the eclipse's share at the ground point.
  vec3 ground_point = start.origin + view_dir * start.length_m;
  vec3 up = normalize(ground_point);
  SkybakeSunAndSkyIrradiance e = skybakeEclipsedIrradiance(
      skybakeIrradianceAtRadius(skybake_radii_m.x, up, up, sun_dir), ground_point, sun_dir, moon);
  v.radiance += v.transmittance * skybake_ground_albedo * (1.0 / SKYBAKE_PI) * (e.sun + e.sky);
  return v;
}

SkybakeRadianceAndTransmittance skybakeReceivedRadiance(vec3 camera_m, vec3 view_dir, vec3 sun_dir, SkybakeMoon moon) {
  SkybakeRay start = skybakeEnterAtmosphere(camera_m, view_dir);
  if (!start.inside) return SkybakeRadianceAndTransmittance(vec4(0.0), vec4(1.0));
  return skybakeReceivedRadiance(camera_m, view_dir, sun_dir, moon,
                                 skybakeEclipseSkylight(start.origin, sun_dir, moon));
}

#ifndef SKYBAKE_NO_RADIANCE_TO_POINT
// Radiance to the point camera_m + view_dir * distance_m under an eclipse,
// the skylight share at the segment's start given (Sky::radianceToPoint(...,
// moon, camera_skylight)): the segment's single scattering integrated with
// the moon's shadow, and the plain radiance to the point less the same
// integral without the moon (what the tables scattered more than once)
// scaled by the share. The same float caveat as skybakeRadianceAlongRayTo's.
SkybakeRadianceAndTransmittance skybakeRadianceAlongRayTo(vec3 camera_m, vec3 view_dir, float distance_m, vec3 sun_dir,
                                                          SkybakeMoon moon, vec4 camera_skylight) {
  SkybakeRadianceAndTransmittance v = skybakeRadianceAlongRayTo(camera_m, view_dir, distance_m, sun_dir, 0.0);
  // A bake without radiance to points gives none, eclipse or not.
  if (!(distance_m > 0.0) || skybake_outputs.x == 0) return v;
  SkybakeRay s = skybakeEnterAtmosphere(camera_m, view_dir);
  float d = min(distance_m - s.moved_m, s.length_m);
  if (!s.inside || d <= 0.0 || !skybakeMoonHidesSunNear(s.origin, sun_dir, moon)) return v;
  float mu_s = skybakeClampCosine(dot(s.origin, sun_dir) / s.r);
  float nu = skybakeClampCosine(dot(view_dir, sun_dir));
  SkybakeMoonAlongRay along = SkybakeMoonAlongRay(moon, s.origin, view_dir, sun_dir);
  SkybakeSingleScatteringPastMoon integral = skybakeIntegrateSingleScattering(
      s.r, s.mu, mu_s, nu, s.ends_on_ground, 0.0, d, SKYBAKE_ECLIPSE_SINGLE_SCATTERING_SEGMENTS, along);
  vec4 multiple = max(v.radiance - skybakeSingleScatteringRadiance(integral.plain, nu), vec4(0.0));
  v.radiance = multiple * camera_skylight + skybakeSingleScatteringRadiance(integral.past_moon, nu);
  return v;
}

// The same with the skylight share computed at the segment's start
// (Sky::radianceToPoint(..., moon)): 4096 kernel points, so where many
// points are seen from one camera, compute the share once.
SkybakeRadianceAndTransmittance skybakeRadianceAlongRayTo(vec3 camera_m, vec3 view_dir, float distance_m, vec3 sun_dir,
                                                          SkybakeMoon moon) {
  SkybakeRay start = skybakeEnterAtmosphere(camera_m, view_dir);
  if (!(distance_m > 0.0) || !start.inside)
    return skybakeRadianceAlongRayTo(camera_m, view_dir, distance_m, sun_dir, 0.0);
  return skybakeRadianceAlongRayTo(camera_m, view_dir, distance_m, sun_dir, moon,
                                   skybakeEclipseSkylight(start.origin, sun_dir, moon));
}

// Radiance scattered toward `camera_m` between it and `point_m` under an
// eclipse, and the transmittance between them (Sky::radianceToPoint(...,
// moon[, camera_skylight])).
SkybakeRadianceAndTransmittance skybakeRadianceToPoint(vec3 camera_m, vec3 point_m, vec3 sun_dir, SkybakeMoon moon,
                                                       vec4 camera_skylight) {
  vec3 offset = point_m - camera_m;
  float distance_m = length(offset);
  if (!(distance_m > 0.0)) return SkybakeRadianceAndTransmittance(vec4(0.0), vec4(1.0));
  return skybakeRadianceAlongRayTo(camera_m, offset / distance_m, distance_m, sun_dir, moon, camera_skylight);
}

SkybakeRadianceAndTransmittance skybakeRadianceToPoint(vec3 camera_m, vec3 point_m, vec3 sun_dir, SkybakeMoon moon) {
  vec3 offset = point_m - camera_m;
  float distance_m = length(offset);
  if (!(distance_m > 0.0)) return SkybakeRadianceAndTransmittance(vec4(0.0), vec4(1.0));
  return skybakeRadianceAlongRayTo(camera_m, offset / distance_m, distance_m, sun_dir, moon);
}
#endif  // SKYBAKE_NO_RADIANCE_TO_POINT

#endif  // SKYBAKE_NO_ECLIPSE_LOOKUPS
