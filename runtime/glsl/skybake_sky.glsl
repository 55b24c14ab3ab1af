// skybake GLSL library (README.md gives the files' order): the lookups of skybake::Sky
// (runtime/sky.h), same geometry rules, same results up to float
// arithmetic. Positions in metres from the planet's centre, unit directions.
//
// Where the C++ throws for a part the bake left out (radiance to points,
// irradiance) these return 0 radiance or irradiance; skybake_outputs says
// what the bake offers.

// Below this sun zenith cosine single scattering is integrated along the
// ray, fully from the horizon down (Sky::integratedSingleScatteringWeight).
float skybakeIntegratedSingleScatteringWeight(float mu_s) {
  float x = clamp(1.0 - mu_s / SKYBAKE_INTEGRATED_SINGLE_SCATTERING_TOP_COSINE, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

// A sun outside the baked sun angles moved to the nearest (Sky::withBakedSun).
float skybakeBakedMuS(float mu_s) { return clamp(mu_s, skybake_baked_sun_cosines.x, skybake_baked_sun_cosines.y); }

// Blends single scattering from the tables (`s`) with the integral along
// the ray, by the weight of the lower of the baked suns the tables are
// read under (Sky::singleScattering).
// A program all of whose lookups start their rays under a sun above the
// horizon where the weight is 0 (a camera in the atmosphere: every ray
// starts where it is; skybake::gl::daylightLookupsSuffice) may define
// SKYBAKE_DAYLIGHT_LOOKUPS_ONLY and is spared compiling the integral and
// the tables' geometric blends (skybakeScattering). Under another sun its
// lookups would be wrong.
SkybakeSingleScattering skybakeBlendInIntegratedSingleScattering(SkybakeSingleScattering s, float r, float mu,
                                                                  float baked_mu_s, float nu, bool ground,
                                                                  float t_start, float t_end, float weight) {
#ifndef SKYBAKE_DAYLIGHT_LOOKUPS_ONLY
  if (weight > 0.0) {
    SkybakeSingleScattering integrated = skybakeIntegrateSingleScattering(
        r, mu, baked_mu_s, nu, ground, t_start, t_end, SKYBAKE_LOOKUP_SINGLE_SCATTERING_SEGMENTS);
    s.rayleigh += (integrated.rayleigh - s.rayleigh) * weight;
    s.mie += (integrated.mie - s.mie) * weight;
  }
#endif
  return s;
}

vec4 skybakeSingleScatteringRadiance(SkybakeSingleScattering s, float nu) {
  return s.rayleigh * skybakeRayleighPhase(nu) + s.mie * skybakeMiePhase(nu);
}

// skybakeSkyRadiance before its parts are summed (Sky::skyRadianceParts):
// single scattering without its phase functions, and multiple scattering,
// for the lookups that weigh them apart (the eclipse lookups).
struct SkybakeSkyRadianceParts {
  bool inside;            // false: the ray misses the atmosphere
  SkybakeRay start;       // the ray from where it is inside the atmosphere
  float mu_s, nu;
  float lit_from_m;       // where scattering starts along start (past a light shaft's shadow)
  SkybakeSingleScattering single;
  vec4 multiple;
  vec4 transmittance;
};

#ifndef SKYBAKE_BAKE_HAS_GROUND_VIEWS
// A ray that ends on the ground in a bake whose tables hold no such rays,
// over [t_start, t_end], integrated along it (Sky::groundRayRadiance);
// (r_p, mu_p, mu_s_p) the same ray from t_start, to_start the transmittance
// over [0, t_start].
void skybakeGroundRayRadiance(float r, float mu, float mu_s, float nu, float t_start, float t_end, float r_p,
                              float mu_p, float mu_s_p, vec4 to_start, inout SkybakeSkyRadianceParts parts) {
  parts.single = skybakeIntegrateSingleScattering(r, mu, skybakeBakedMuS(mu_s), nu, true, t_start, t_end,
                                                  SKYBAKE_GROUND_RAY_SUBINTERVALS);
  SkybakeRadianceAndTransmittance multiple = skybakeDirectSegmentRadiance(
      r_p, mu_p, skybakeBakedMuS(mu_s_p), nu, max(t_end - t_start, 0.0), SKYBAKE_GROUND_RAY_SUBINTERVALS, false);
  parts.multiple = multiple.radiance * to_start;
}
#endif

SkybakeSkyRadianceParts skybakeSkyRadianceParts(vec3 camera_m, vec3 view_dir, vec3 sun_dir, float shadow_length_m) {
  SkybakeSkyRadianceParts parts;
  parts.start = skybakeEnterAtmosphere(camera_m, view_dir);
  parts.inside = parts.start.inside;
  parts.mu_s = 1.0;
  parts.nu = 1.0;
  parts.lit_from_m = 0.0;
  parts.single = SkybakeSingleScattering(vec4(0.0), vec4(0.0));
  parts.multiple = vec4(0.0);
  parts.transmittance = vec4(1.0);
  if (!parts.inside) return parts;
  SkybakeRay start = parts.start;
  float bottom = skybake_radii_m.x;
  float r = start.r;
  float mu = start.mu;
  float mu_s = skybakeClampCosine(dot(start.origin, sun_dir) / r);
  float nu = skybakeClampCosine(dot(view_dir, sun_dir));
  parts.mu_s = mu_s;
  parts.nu = nu;
  bool ground = start.ends_on_ground;
  parts.transmittance = ground ? exp(-skybakeOpticalDepthAlongRay(r, mu, start.length_m, true))
                               : exp(-skybakeOpticalDepthToTop(r, mu));
  // Only the part beyond the shadow scatters, seen through the shadowed part.
  float shadow = clamp(shadow_length_m - start.moved_m, 0.0, start.length_m);
  float r_p = r;
  float mu_p = mu;
  float mu_s_p = mu_s;
  vec4 shadow_transmittance = vec4(1.0);
  if (shadow > 0.0) {
    r_p = skybakeShellRadiusAlongRay(r, mu, shadow);
    mu_p = skybakeCosineAlongRay(r, mu, shadow, r_p);
    mu_s_p = skybakeClampCosine((r * mu_s + shadow * nu) / r_p);
    shadow_transmittance = exp(-skybakeOpticalDepthAlongRay(r, mu, shadow, ground));
  }
  parts.lit_from_m = shadow;
  // A ground ray of a bake whose table holds no rays to the ground (a
  // scene's without views below the horizon) is integrated. A program that
  // knows its bake holds them (skybake_parts.x == 1: every bake but those)
  // defines SKYBAKE_BAKE_HAS_GROUND_VIEWS and is spared compiling this path,
  // half the sky lookup's compile time on llvmpipe.
#ifndef SKYBAKE_BAKE_HAS_GROUND_VIEWS
  if (ground && skybake_parts.x == 0) {
    skybakeGroundRayRadiance(r, mu, mu_s, nu, shadow, start.length_m, r_p, mu_p, mu_s_p, shadow_transmittance, parts);
    return parts;
  }
#endif
  float baked_mu_s = skybakeBakedMuS(mu_s);
  // The lower of the two suns the tables would be read under (Sky::singleScattering).
  float weight = skybakeIntegratedSingleScatteringWeight(min(baked_mu_s, skybakeBakedMuS(mu_s_p)));
  SkybakeSkyTables tables = skybakeSkyTables(r_p, mu_p, mu_s_p, nu, ground);
  SkybakeSingleScattering single = SkybakeSingleScattering(vec4(0.0), vec4(0.0));
  if (weight < 1.0) single = SkybakeSingleScattering(tables.rayleigh, tables.mie);
  single.rayleigh *= shadow_transmittance;
  single.mie *= shadow_transmittance;
  parts.single =
      skybakeBlendInIntegratedSingleScattering(single, r, mu, baked_mu_s, nu, ground, shadow, start.length_m, weight);
  parts.multiple = tables.multiple * skybakeMultipleShape(r_p - bottom, nu) * shadow_transmittance;
  return parts;
}

// Radiance of the sky seen from `camera_m` along `view_dir`, and the
// transmittance to where the ray leaves the atmosphere or meets the ground;
// the ground's own light excluded. shadow_length_m: the ray's first part in
// the shadow of scene geometry (light shafts), 0 for none.
SkybakeRadianceAndTransmittance skybakeSkyRadiance(vec3 camera_m, vec3 view_dir, vec3 sun_dir, float shadow_length_m) {
  SkybakeSkyRadianceParts p = skybakeSkyRadianceParts(camera_m, view_dir, sun_dir, shadow_length_m);
  if (!p.inside) return SkybakeRadianceAndTransmittance(vec4(0.0), vec4(1.0));
  return SkybakeRadianceAndTransmittance(skybakeSingleScatteringRadiance(p.single, p.nu) + p.multiple,
                                         p.transmittance);
}

SkybakeRadianceAndTransmittance skybakeSkyRadiance(vec3 camera_m, vec3 view_dir, vec3 sun_dir) {
  return skybakeSkyRadiance(camera_m, view_dir, sun_dir, 0.0);
}

// Sun and sky irradiance at radius r (clamped to the shell) on a surface with
// unit `normal`, `up` the local vertical (Sky::irradiance).
SkybakeSunAndSkyIrradiance skybakeIrradianceAtRadius(float r, vec3 up, vec3 normal, vec3 sun_dir) {
  if (skybake_outputs.y == 0) return SkybakeSunAndSkyIrradiance(vec4(0.0), vec4(0.0));
  r = clamp(r, skybake_radii_m.x, skybake_radii_m.y);
  float mu_s = skybakeClampCosine(dot(up, sun_dir));
  vec4 sky = skybakeIrradianceTable(r, mu_s) * (0.5 * (1.0 + dot(normal, up)));
  vec4 sun = skybake_sun_irradiance * skybakeTransmittanceToSun(r, mu_s) * max(dot(normal, sun_dir), 0.0);
  return SkybakeSunAndSkyIrradiance(sun, sky);
}

// Sun and sky irradiance, W m^-2 nm^-1, on a surface at `point_m` with unit
// `normal`; the sky part as a horizontal surface's scaled by (1 + normal . up) / 2.
SkybakeSunAndSkyIrradiance skybakeSunAndSkyIrradiance(vec3 point_m, vec3 normal, vec3 sun_dir) {
  float r = length(point_m);
  vec3 up = r > 0.0 ? point_m / r : vec3(0.0, 0.0, 1.0);
  return skybakeIrradianceAtRadius(r, up, normal, sun_dir);
}

// What a viewer receives along the ray, the sun disk aside: the sky plus,
// for a ray that ends on the ground, the transmitted radiance of the
// Lambertian ground lit by sun and sky (Sky::receivedRadiance). The ground
// point is taken on the ground's sphere, where the ray ends.
SkybakeRadianceAndTransmittance skybakeReceivedRadiance(vec3 camera_m, vec3 view_dir, vec3 sun_dir) {
  SkybakeRadianceAndTransmittance v = skybakeSkyRadiance(camera_m, view_dir, sun_dir, 0.0);
  SkybakeRay start = skybakeEnterAtmosphere(camera_m, view_dir);
  if (!start.inside || !start.ends_on_ground) return v;
  vec3 ground_point = start.origin + view_dir * start.length_m;
  vec3 up = normalize(ground_point);
  SkybakeSunAndSkyIrradiance e = skybakeIrradianceAtRadius(skybake_radii_m.x, up, up, sun_dir);
  v.radiance += v.transmittance * skybake_ground_albedo * (1.0 / SKYBAKE_PI) * (e.sun + e.sky);
  return v;
}

// Radiance of the sun disk above the atmosphere, W m^-2 sr^-1 nm^-1; times a
// view ray's transmittance where skybakeInSunDisk.
vec4 skybakeSolarRadiance() { return skybake_solar_radiance; }

// ---- radiance to a point (aerial perspective) ----
// A GLSL compiler spends time on every function of its source, called or
// not (Mesa's compiles each before linking drops the unused): a program
// that looks up no radiance to points may define
// SKYBAKE_NO_RADIANCE_TO_POINT and is spared these.
#ifndef SKYBAKE_NO_RADIANCE_TO_POINT

struct SkybakeSegmentScattering {
  vec4 rayleigh;  // over the Rayleigh phase
  vec4 mie;       // over the Mie phase
  vec4 multiple;  // radiance, the shape applied at each end
  float far_mu_s;  // the sun's zenith cosine at the segment's far end
};

// In-scattering over [0, d] of the ray (r, mu) as the scattering to the
// ray's end seen from its start minus that seen from d, attenuated.
SkybakeSegmentScattering skybakeSegmentScattering(float r, float mu, float mu_s, float nu, float d, float shadow,
                                                  bool ground, vec4 transmittance) {
  float bottom = skybake_radii_m.x;
  float d_p = max(d - shadow, 0.0);
  float r_p = skybakeShellRadiusAlongRay(r, mu, d_p);
  float mu_p = skybakeCosineAlongRay(r, mu, d_p, r_p);
  float mu_s_p = skybakeClampCosine((r * mu_s + d_p * nu) / r_p);
  vec4 shadow_transmittance =
      shadow == 0.0 ? transmittance : exp(-skybakeOpticalDepthAlongRay(r, mu, d_p, ground));
  SkybakeSegmentScattering s;
  s.far_mu_s = mu_s_p;
  s.rayleigh =
      max(skybakeScattering(skybake_single_rayleigh, SKYBAKE_SCALE_SINGLE_RAYLEIGH, r, mu, mu_s, nu, ground) -
              shadow_transmittance * skybakeScattering(skybake_single_rayleigh, SKYBAKE_SCALE_SINGLE_RAYLEIGH, r_p, mu_p,
                                                       mu_s_p, nu, ground),
          vec4(0.0));
  s.mie = vec4(0.0);
  if (skybake_parts.y != 0) {
    s.mie = max(skybakeScattering(skybake_single_mie, SKYBAKE_SCALE_SINGLE_MIE, r, mu, mu_s, nu, ground) -
                    shadow_transmittance *
                        skybakeScattering(skybake_single_mie, SKYBAKE_SCALE_SINGLE_MIE, r_p, mu_p, mu_s_p, nu, ground),
                vec4(0.0));
  }
  s.multiple =
      max(skybakeScattering(skybake_multiple_scattering, SKYBAKE_SCALE_MULTIPLE_SCATTERING, r, mu, mu_s, nu, ground) *
                  skybakeMultipleShape(r - bottom, nu) -
              shadow_transmittance * skybakeMultipleShape(r_p - bottom, nu) *
                  skybakeScattering(skybake_multiple_scattering, SKYBAKE_SCALE_MULTIPLE_SCATTERING, r_p, mu_p, mu_s_p,
                                    nu, ground),
          vec4(0.0));
  return s;
}

// The segment's radiance from the tables (Sky::differenceSegmentRadiance):
// blended across the horizon, single Mie faded out as the sun sets, single
// scattering integrated with the sun below the horizon.
vec4 skybakeDifferenceSegmentRadiance(float r, float mu, float mu_s, float nu, float d, float shadow, bool ground,
                                      vec4 transmittance) {
  SkybakeSegmentScattering s = skybakeSegmentScattering(r, mu, mu_s, nu, d, shadow, ground, transmittance);
  float from_horizon = mu - skybakeTangentZenithCosine(r, skybake_radii_m.x);
  if (abs(from_horizon) < SKYBAKE_HORIZON_BLEND_COSINE && skybake_parts.x != 0) {
    SkybakeSegmentScattering other = skybakeSegmentScattering(r, mu, mu_s, nu, d, shadow, !ground, transmittance);
    float w_sky = 0.5 + 0.5 * from_horizon / SKYBAKE_HORIZON_BLEND_COSINE;
    float w_this = ground ? 1.0 - w_sky : w_sky;
    s.rayleigh = s.rayleigh * w_this + other.rayleigh * (1.0 - w_this);
    s.mie = s.mie * w_this + other.mie * (1.0 - w_this);
    s.multiple = s.multiple * w_this + other.multiple * (1.0 - w_this);
  }
  float mie_fade = clamp(mu_s / SKYBAKE_MIE_TWILIGHT_FADE_COSINE, 0.0, 1.0);
  float baked_mu_s = skybakeBakedMuS(mu_s);
  float weight = skybakeIntegratedSingleScatteringWeight(min(baked_mu_s, skybakeBakedMuS(s.far_mu_s)));
  SkybakeSingleScattering single = SkybakeSingleScattering(vec4(0.0), vec4(0.0));
  if (weight < 1.0) single = SkybakeSingleScattering(s.rayleigh, s.mie * (mie_fade * mie_fade * (3.0 - 2.0 * mie_fade)));
  single = skybakeBlendInIntegratedSingleScattering(single, r, mu, baked_mu_s, nu, ground, 0.0, max(d - shadow, 0.0),
                                                    weight);
  return skybakeSingleScatteringRadiance(single, nu) + s.multiple;
}

// Radiance scattered toward `camera_m` over the first distance_m of the ray
// along unit `view_dir`, and the transmittance over it: radiance to the
// point camera_m + view_dir * distance_m (Sky::radianceToPoint). Renderers
// that know the distance to a surface should call this rather than
// skybakeRadianceToPoint: the offset from camera to point computed in float
// from two planet-sized positions is off by up to half a metre.
SkybakeRadianceAndTransmittance skybakeRadianceAlongRayTo(vec3 camera_m, vec3 view_dir, float distance_m, vec3 sun_dir,
                                                          float shadow_length_m) {
  SkybakeRadianceAndTransmittance none = SkybakeRadianceAndTransmittance(vec4(0.0), vec4(1.0));
  if (!(distance_m > 0.0)) return none;
  SkybakeRay start = skybakeEnterAtmosphere(camera_m, view_dir);
  float d = distance_m - start.moved_m;
  if (!start.inside || d <= 0.0) return none;
  float r = start.r;
  float mu = start.mu;
  float mu_s = skybakeClampCosine(dot(start.origin, sun_dir) / r);
  float nu = skybakeClampCosine(dot(view_dir, sun_dir));
  float shadow = max(shadow_length_m - start.moved_m, 0.0);
  bool ground = start.ends_on_ground;
  if (skybake_outputs.x == 0) {
    // Left out of the bake: no radiance, the transmittance still known.
    return SkybakeRadianceAndTransmittance(vec4(0.0), exp(-skybakeOpticalDepthAlongRay(r, mu, d, ground)));
  }
  float scattering_length_m = max(d - shadow, 0.0);
  float direct_weight = max(
      clamp((SKYBAKE_DIRECT_SEGMENT_MAX_LENGTH_M - scattering_length_m) /
                (SKYBAKE_DIRECT_SEGMENT_MAX_LENGTH_M - SKYBAKE_DIFFERENCE_SEGMENT_MIN_LENGTH_M),
            0.0, 1.0),
      ground && skybake_parts.x == 0 ? 1.0 : skybakeIntegratedSingleScatteringWeight(skybakeBakedMuS(mu_s)));
  vec4 radiance = vec4(0.0);
  vec4 transmittance = vec4(0.0);
  if (direct_weight > 0.0) {
    SkybakeRadianceAndTransmittance direct = skybakeDirectSegmentRadiance(
        r, mu, mu_s, nu, scattering_length_m, SKYBAKE_DIRECT_SEGMENT_SUBINTERVALS, true);
    radiance += direct.radiance * direct_weight;
    // With a shadow the segment to the point is longer than the lit part.
    transmittance += (shadow > 0.0 ? exp(-skybakeOpticalDepthAlongRay(r, mu, d, ground)) : direct.transmittance) *
                     direct_weight;
  }
  if (direct_weight < 1.0) {
    float w = 1.0 - direct_weight;
    vec4 table_transmittance = exp(-skybakeOpticalDepthAlongRay(r, mu, d, ground));
    radiance += skybakeDifferenceSegmentRadiance(r, mu, mu_s, nu, d, shadow, ground, table_transmittance) * w;
    transmittance += table_transmittance * w;
  }
  return SkybakeRadianceAndTransmittance(radiance, transmittance);
}

// Radiance scattered toward `camera_m` between it and `point_m`, and the
// transmittance between them (aerial perspective).
SkybakeRadianceAndTransmittance skybakeRadianceToPoint(vec3 camera_m, vec3 point_m, vec3 sun_dir,
                                                       float shadow_length_m) {
  vec3 offset = point_m - camera_m;
  float distance_m = length(offset);
  if (!(distance_m > 0.0)) return SkybakeRadianceAndTransmittance(vec4(0.0), vec4(1.0));
  return skybakeRadianceAlongRayTo(camera_m, offset / distance_m, distance_m, sun_dir, shadow_length_m);
}

#endif  // SKYBAKE_NO_RADIANCE_TO_POINT

// Transmittance along the straight segment from a_m to b_m (0 where it
// passes through the ground).
vec4 skybakeTransmittance(vec3 a_m, vec3 b_m) {
  vec3 offset = b_m - a_m;
  float distance_m = length(offset);
  if (!(distance_m > 0.0)) return vec4(1.0);
  vec3 dir = offset / distance_m;
  SkybakeRay start = skybakeEnterAtmosphere(a_m, dir);
  float d = distance_m - start.moved_m;
  if (!start.inside || d <= 0.0) return vec4(1.0);
  bool ground = start.ends_on_ground;
  float length_m = start.length_m;
  if (ground && d > length_m) {
    // Closest approach to the centre at least bottom - tolerance: the ray
    // only grazes the ground. closest^2 - bottom^2 = rho^2 - (r mu)^2.
    float bottom = skybake_radii_m.x;
    float rho = skybakeDistanceToHorizon(start.r);
    float rmu = start.r * start.mu;
    float tolerance_m = SKYBAKE_GROUND_GRAZE_TOLERANCE_M;
    bool grazes = rho * rho - rmu * rmu >= -(2.0 * bottom - tolerance_m) * tolerance_m;
    if (!grazes) return vec4(0.0);
    ground = false;
    length_m = skybakeDistanceToOuterSphere(start.r, start.mu, skybake_radii_m.y);
  }
  float inside = min(d, length_m);
  return exp(-skybakeOpticalDepthAlongRay(start.r, start.mu, inside, ground));
}

// Luminance (cd m^-2) of a radiance these lookups return, or illuminance
// (lx) of an irradiance, whatever the bake's channels hold
// (Sky::luminance): the per-channel weights come from C++.
float skybakeLuminance(vec4 value) { return dot(skybake_luminance_weights, value); }

// Whether the channels are CIE X, Y, Z (a colour bake) rather than wavelengths.
bool skybakeChannelsAreCieXyz() { return skybake_outputs.w == 1; }
