// skybake GLSL library (README.md gives the files' order): the interpolated
// table lookups (runtime/tables/table_sampler.h on the CPU), the
// multiple-scattering shape (runtime/physics/multiple_scattering_phase.h) included.
// Where a configuration lives in the tables, the interpolation weights and
// the night continuation's formula are kernel files the C++ shares
// (data_formats/kernel/texture_coordinates.glsl,
// runtime/kernel/table_weights.glsl, runtime/kernel/night_continuation.glsl),
// read before this one; here they are given the bake's constants from the
// uniform block and applied to the textures, read with texelFetch.

// One row of a 2D table, interpolated along x.
vec4 skybakeSampleRow(sampler2D table, SkybakeAxisLerp x, int row) {
  vec4 a = texelFetch(table, ivec2(x.i0, row), 0);
  vec4 b = texelFetch(table, ivec2(x.i1, row), 0);
  return a + (b - a) * x.w1;
}

vec4 skybakeSampleBilinear(sampler2D table, SkybakeAxisLerp x, SkybakeAxisLerp y) {
  vec4 a = skybakeSampleRow(table, x, y.i0);
  vec4 b = skybakeSampleRow(table, x, y.i1);
  return a + (b - a) * y.w1;
}

// The kernel's blend per channel: geometric where both texels are positive
// and far apart, linear where they are close (table_weights.glsl).
vec4 skybakeBlendGeometricWhereSteep(vec4 a, vec4 b, float w) {
  return vec4(skybakeBlendGeometricWhereSteep(a.x, b.x, w), skybakeBlendGeometricWhereSteep(a.y, b.y, w),
              skybakeBlendGeometricWhereSteep(a.z, b.z, w), skybakeBlendGeometricWhereSteep(a.w, b.w, w));
}

// The same with the geometric blend's share given, where both are positive.
vec4 skybakeBlendGeometricWherePositive(vec4 a, vec4 b, float w, float geometric_share) {
  return vec4(skybakeBlendGeometricWherePositive(a.x, b.x, w, geometric_share),
              skybakeBlendGeometricWherePositive(a.y, b.y, w, geometric_share),
              skybakeBlendGeometricWherePositive(a.z, b.z, w, geometric_share),
              skybakeBlendGeometricWherePositive(a.w, b.w, w, geometric_share));
}

vec4 skybakeBlendAcross(vec4 a, vec4 b, float w, bool geometric) {
  return geometric ? skybakeBlendGeometricWhereSteep(a, b, w) : a + (b - a) * w;
}

// The 4D tables' texel (r, mu, mu_s, nu), before its slice's scale.
// A 4D table's sun texels as uploaded: x how many, y the first of the
// whole axis. The single-scattering tables leave out the suns below the
// horizon, where no lookup reads them (runtime/tables/gpu_tables.h,
// skybakeSingleScatteringFirstSunTexel); the others hold the whole axis.
ivec2 skybakeUploadedSunTexels(sampler3D table) {
  int uploaded = max(textureSize(table, 0).x / skybake_scattering_size.w, 1);
  return ivec2(uploaded, max(skybake_scattering_size.z - uploaded, 0));
}

// Texel (i_r, i_mu, i_mu_s, i_nu) of a 4D table whose sun texels are `suns`
// (skybakeUploadedSunTexels); a sun below the first uploaded reads the first.
vec4 skybakeTexel4D(sampler3D table, ivec2 suns, int i_r, int i_mu, int i_mu_s, int i_nu) {
  return texelFetch(table, ivec3(i_nu * suns.x + max(i_mu_s - suns.y, 0), i_mu, i_r), 0);
}

// The scales of the four (r, mu_s) slices around a lookup, lane `scale` of
// skybake_slice_scales: x (r0, mu_s0), y (r0, mu_s1), z (r1, mu_s0), w (r1, mu_s1).
vec4 skybakeSliceScales(int scale, SkybakeAxisLerp r, SkybakeAxisLerp mu_s) {
  return vec4(texelFetch(skybake_slice_scales, ivec2(mu_s.i0, r.i0), 0)[scale],
              texelFetch(skybake_slice_scales, ivec2(mu_s.i1, r.i0), 0)[scale],
              texelFetch(skybake_slice_scales, ivec2(mu_s.i0, r.i1), 0)[scale],
              texelFetch(skybake_slice_scales, ivec2(mu_s.i1, r.i1), 0)[scale]);
}

// A 4D table's texture coordinates (texture_mapping.h, ScatteringCoord).
struct SkybakeScatteringCoord {
  float u_nu;
  float u_mu_s;
  float u_mu;
  float u_r;
};

// The eight (r, mu, nu) corners around a 4D lookup: in each of the two nu
// slices the four (r, mu) corners' texel pairs are blended across mu_s
// (geometrically where `geometric` says) and summed bilinearly, then the
// slices blended across nu. The lookups loop over the corners rather than
// write out eight copies: a shader compiler then builds one texel pair and
// one blend across mu_s per table instead of eight, which is most of a sky
// program's compile time on a CPU rasterizer (Mesa's llvmpipe: the browser
// viewer's first frame).
struct SkybakeCorner {
  int i_r, i_mu, i_nu;
  bool upper_r;   // at r.i1: the slice scales' z and w
  bool upper_nu;  // in the nu.i1 slice
  float weight;   // bilinear in (r, mu)
};

// The interpolation on each of a 4D table's axes at texture coordinates `c`.
struct SkybakeLerp4D {
  SkybakeAxisLerp r, mu, mu_s, nu;
};

SkybakeLerp4D skybakeLerp4D(SkybakeScatteringCoord c, ivec4 size) {
  return SkybakeLerp4D(skybakeAxisLerp(c.u_r, size.x), skybakeAxisLerp(c.u_mu, size.y),
                       skybakeAxisLerp(c.u_mu_s, size.z), skybakeAxisLerpNu(c.u_nu, size.w));
}

SkybakeCorner skybakeCorner(int corner, SkybakeAxisLerp r, SkybakeAxisLerp mu, SkybakeAxisLerp nu) {
  SkybakeCorner k;
  k.upper_r = (corner & 1) != 0;
  bool upper_mu = (corner & 2) != 0;
  k.upper_nu = corner >= 4;
  k.i_r = k.upper_r ? r.i1 : r.i0;
  k.i_mu = upper_mu ? mu.i1 : mu.i0;
  k.i_nu = k.upper_nu ? nu.i1 : nu.i0;
  k.weight = (k.upper_r ? r.w1 : 1.0 - r.w1) * (upper_mu ? mu.w1 : 1.0 - mu.w1);
  return k;
}

// A corner's texel pair across mu_s, each times its slice's scale (`scales`
// of skybakeSliceScales), blended.
vec4 skybakeCornerAcrossMuS(sampler3D table, ivec2 suns, SkybakeCorner k, SkybakeAxisLerp mu_s, vec4 scales,
                            bool geometric) {
  vec2 slice_scales = k.upper_r ? scales.zw : scales.xy;
  return skybakeBlendAcross(skybakeTexel4D(table, suns, k.i_r, k.i_mu, mu_s.i0, k.i_nu) * slice_scales.x,
                            skybakeTexel4D(table, suns, k.i_r, k.i_mu, mu_s.i1, k.i_nu) * slice_scales.y, mu_s.w1,
                            geometric);
}

// A 4D table of `size` texels (r, mu, mu_s, nu), `scale` its SKYBAKE_SCALE_*
// lane, at texture coordinates `c`.
vec4 skybakeSample4DOfSize(sampler3D table, ivec4 size, int scale, SkybakeScatteringCoord c, bool geometric) {
  SkybakeLerp4D l = skybakeLerp4D(c, size);
  vec4 scales = skybakeSliceScales(scale, l.r, l.mu_s);
  ivec2 suns = skybakeUploadedSunTexels(table);
  vec4 lower_nu = vec4(0.0);
  vec4 upper_nu = vec4(0.0);
  for (int corner = 0; corner < 8; ++corner) {
    SkybakeCorner k = skybakeCorner(corner, l.r, l.mu, l.nu);
    vec4 v = skybakeCornerAcrossMuS(table, suns, k, l.mu_s, scales, geometric) * k.weight;
    if (k.upper_nu) {
      upper_nu += v;
    } else {
      lower_nu += v;
    }
  }
  return skybakeBlendAcross(lower_nu, upper_nu, l.nu.w1, geometric);
}

// A radiance table (skybake_scattering_size) at texture coordinates `c`.
vec4 skybakeSample4D(sampler3D table, int scale, SkybakeScatteringCoord c, bool geometric) {
  return skybakeSample4DOfSize(table, skybake_scattering_size, scale, c, geometric);
}

// ---- optical depth (2D: u = mu, v = r) ----

// The optical-depth table's r axis and mu constants at one radius.
struct SkybakeOpticalDepthAtR {
  float r;
  float dist_min_m;  // straight up
  float dist_max_m;  // toward the horizon
  SkybakeAxisLerp r_lerp;
};

SkybakeOpticalDepthAtR skybakeOpticalDepthAtR(float r) {
  float rho = skybakeDistanceToHorizon(r);
  float H = skybake_radii_m.z;
  int size_r = skybake_table_2d_size.y;
  return SkybakeOpticalDepthAtR(r, skybake_radii_m.y - r, rho + H,
                                skybakeAxisLerp(skybakeOpticalDepthCoordR(rho, H, size_r), size_r));
}

float skybakeOpticalDepthMuCoord(SkybakeOpticalDepthAtR at, float mu) {
  return skybakeOpticalDepthCoordMu(at.r, mu, skybake_radii_m.y, at.dist_min_m, at.dist_max_m,
                                    skybake_table_2d_size.x);
}

vec4 skybakeOpticalDepthAtCoord(SkybakeOpticalDepthAtR at, float u_mu) {
  return skybakeSampleBilinear(skybake_optical_depth, skybakeAxisLerp(u_mu, skybake_table_2d_size.x), at.r_lerp);
}

// Optical depth from (r, mu) to the top boundary, the ground ignored.
vec4 skybakeOpticalDepthToTop(float r, float mu) {
  SkybakeOpticalDepthAtR at = skybakeOpticalDepthAtR(r);
  return skybakeOpticalDepthAtCoord(at, skybakeOpticalDepthMuCoord(at, mu));
}

// The same from the table of the single-scattering integral's pass g
// (skybake_integral_passes): the bake's own for a bake of one pass, a
// colour bake's wavelength group g's (one lane per wavelength) otherwise.
vec4 skybakePassOpticalDepthToTop(int g, float r, float mu) {
  SkybakeOpticalDepthAtR at = skybakeOpticalDepthAtR(r);
  SkybakeAxisLerp x = skybakeAxisLerp(skybakeOpticalDepthMuCoord(at, mu), skybake_table_2d_size.x);
  int first_row = skybake_integral_passes.y + g * skybake_integral_passes.z;
  vec4 a = skybakeSampleRow(skybake_optical_depth, x, first_row + at.r_lerp.i0);
  vec4 b = skybakeSampleRow(skybake_optical_depth, x, first_row + at.r_lerp.i1);
  return a + (b - a) * at.r_lerp.w1;
}

// Optical depth over [0, d] of the ray (r, mu), as a difference of depths to
// the top, both legs reversed (pointing up) for a ray to the ground or a
// segment that ends before the ray's lowest point (TableSampler::opticalDepthAlongRay).
vec4 skybakeOpticalDepthAlongRay(float r, float mu, float d, bool ray_intersects_ground) {
  float r_d = skybakeShellRadiusAlongRay(r, mu, d);
  float mu_d = skybakeCosineAlongRay(r, mu, d, r_d);
  bool reversed = ray_intersects_ground || d <= -r * mu;
  return reversed ? max(skybakeOpticalDepthToTop(r_d, -mu_d) - skybakeOpticalDepthToTop(r, -mu), vec4(0.0))
                  : max(skybakeOpticalDepthToTop(r, mu) - skybakeOpticalDepthToTop(r_d, mu_d), vec4(0.0));
}

// Transmittance to the sun from radius r, sun zenith cosine mu_s, times the
// part of the disk above the horizon.
vec4 skybakeTransmittanceToSun(float r, float mu_s) {
  float bottom = skybake_radii_m.x;
  float visible = skybakeSunDiskVisibleFraction(mu_s - skybakeTangentZenithCosine(r, bottom),
                                                skybakeSunDiskHalfSizeAtHorizon(bottom, r, skybake_sun_disk.x));
  if (visible <= 0.0) return vec4(0.0);
  return exp(-skybakeOpticalDepthToTop(r, mu_s)) * visible;
}

// ---- scattering (4D) ----

// The unit sun coordinate: 1 at the zenith, 0 at the lowest tabulated sun
// (the kernel's skybakeSunUnitCoord with the bake's constants).
float skybakeMuSUnitCoord(float mu_s) {
  SkybakeSunCoordMap m;
  m.bottom_radius_m = skybake_radii_m.x;
  m.top_radius_m = skybake_radii_m.y;
  m.d_min = skybake_mu_s_map.x;
  m.inverse_d_span = skybake_mu_s_map.y;
  m.inverse_A = skybake_mu_s_map.z;
  m.defined = skybake_mu_s_map.w;
  m.below_share = skybake_mu_s_below.x;
  m.day_coord_at_horizon = skybake_mu_s_below.y;
  m.inverse_mu_s_min = skybake_mu_s_below.z;
  m.horizon_spacing = skybake_mu_s_below.w;
  return skybakeSunUnitCoord(m, mu_s);
}

// A 4D table's texture coordinates at (r, mu, mu_s, nu).
SkybakeScatteringCoord skybakeScatteringCoord(float r, float mu, float mu_s, float nu, bool ray_intersects_ground) {
  ivec4 size = skybake_scattering_size;
  vec4 domain = skybake_scattering_domain;
  float rho = skybakeDistanceToHorizon(r);
  float u_mu = skybakeScatteringCoordMu(r, mu, skybake_radii_m.x, skybake_radii_m.y, rho, skybake_radii_m.z, size.y,
                                        skybake_parts.x != 0, ray_intersects_ground);
  float u_mu_s = skybakeScatteringCoordMuS(skybakeMuSUnitCoord(mu_s), domain.z, domain.w, size.z);
  float u_r = skybakeScatteringCoordR(rho, domain.x, domain.y, size.x);
  return SkybakeScatteringCoord(skybakeScatteringCoordNu(nu), u_mu_s, u_mu, u_r);
}

// ---- the night continuation (runtime/physics/night_sky.h) ----

// The share of the lowest baked sun's tabulated light left with the sun at
// zenith cosine mu_s: 1 at and above it, (1 - tan(d / 2) / tan(span / 2))^p
// at depression d below, 0 from the dark angle on
// (NightContinuation::scaleBelowEdge; no acos, see there).
vec4 skybakeNightScale(float mu_s) {
  if (mu_s >= skybake_night.x) return vec4(1.0);
  float x = skybakeNightScaleBase(mu_s, skybake_night.x, skybake_night.y, skybake_night.z);
  return pow(vec4(x), skybake_night_exponent);  // p >= 1: pow(0, p) is defined
}

// For the 4D tables (TableSampler::nightScale4D): a narrowed scene's tables
// are clamped to its lowest sun instead.
vec4 skybakeNightScale4D(float mu_s) { return skybake_night.w > 0.5 ? skybakeNightScale(mu_s) : vec4(1.0); }

// Whether a 4D lookup blends across mu_s and nu geometrically: with the
// sun below the horizon (radianceBlend). In a program of daylight lookups
// (SKYBAKE_DAYLIGHT_LOOKUPS_ONLY, skybake_sky.glsl) the sun is above it at
// every lookup's start: the blends are linear, the geometric ones not compiled.
bool skybakeGeometricAcrossSun(float mu_s) {
#ifdef SKYBAKE_DAYLIGHT_LOOKUPS_ONLY
  return false;
#else
  return mu_s < 0.0;
#endif
}

// A radiance table at (r, mu, mu_s, nu). `scale`: the table's
// SKYBAKE_SCALE_* lane.
vec4 skybakeScattering(sampler3D table, int scale, float r, float mu, float mu_s, float nu, bool ray_intersects_ground) {
  return skybakeSample4D(table, scale, skybakeScatteringCoord(r, mu, mu_s, nu, ray_intersects_ground),
                         skybakeGeometricAcrossSun(mu_s)) *
         skybakeNightScale4D(mu_s);
}

// The three radiance tables at (r, mu, mu_s, nu), as skybakeScattering
// reads each, together: the sky lookup's Rayleigh and Mie single scattering
// (over their phase functions; Mie 0 in a bake without it) and multiple
// scattering (over its shape). One loop over the corners reads all three,
// with the coordinates, weights and slice scales computed once: a third of
// the code a compiler builds for three lookups.
struct SkybakeSkyTables {
  vec4 rayleigh;
  vec4 mie;
  vec4 multiple;
};

SkybakeSkyTables skybakeSkyTables(float r, float mu, float mu_s, float nu, bool ray_intersects_ground) {
  SkybakeLerp4D l =
      skybakeLerp4D(skybakeScatteringCoord(r, mu, mu_s, nu, ray_intersects_ground), skybake_scattering_size);
  bool geometric = skybakeGeometricAcrossSun(mu_s);
  bool with_mie = skybake_parts.y != 0;
  vec4 rayleigh_scales = skybakeSliceScales(SKYBAKE_SCALE_SINGLE_RAYLEIGH, l.r, l.mu_s);
  vec4 mie_scales = skybakeSliceScales(SKYBAKE_SCALE_SINGLE_MIE, l.r, l.mu_s);
  vec4 multiple_scales = skybakeSliceScales(SKYBAKE_SCALE_MULTIPLE_SCATTERING, l.r, l.mu_s);
  ivec2 single_suns = skybakeUploadedSunTexels(skybake_single_rayleigh);
  ivec2 multiple_suns = ivec2(skybake_scattering_size.z, 0);
  SkybakeSkyTables lower_nu = SkybakeSkyTables(vec4(0.0), vec4(0.0), vec4(0.0));
  SkybakeSkyTables upper_nu = lower_nu;
  for (int corner = 0; corner < 8; ++corner) {
    SkybakeCorner k = skybakeCorner(corner, l.r, l.mu, l.nu);
    vec4 rayleigh =
        skybakeCornerAcrossMuS(skybake_single_rayleigh, single_suns, k, l.mu_s, rayleigh_scales, geometric) * k.weight;
    // A bake without single Mie has a one-texel stand-in: not read.
    vec4 mie = vec4(0.0);
    if (with_mie)
      mie = skybakeCornerAcrossMuS(skybake_single_mie, single_suns, k, l.mu_s, mie_scales, geometric) * k.weight;
    vec4 multiple =
        skybakeCornerAcrossMuS(skybake_multiple_scattering, multiple_suns, k, l.mu_s, multiple_scales, geometric) *
        k.weight;
    if (k.upper_nu) {
      upper_nu.rayleigh += rayleigh;
      upper_nu.mie += mie;
      upper_nu.multiple += multiple;
    } else {
      lower_nu.rayleigh += rayleigh;
      lower_nu.mie += mie;
      lower_nu.multiple += multiple;
    }
  }
  vec4 night = skybakeNightScale4D(mu_s);
  return SkybakeSkyTables(skybakeBlendAcross(lower_nu.rayleigh, upper_nu.rayleigh, l.nu.w1, geometric) * night,
                          skybakeBlendAcross(lower_nu.mie, upper_nu.mie, l.nu.w1, geometric) * night,
                          skybakeBlendAcross(lower_nu.multiple, upper_nu.multiple, l.nu.w1, geometric) * night);
}

#if !defined(SKYBAKE_NO_RADIANCE_TO_POINT) || !defined(SKYBAKE_BAKE_HAS_GROUND_VIEWS)
// The multiple-scattering density table: mu linear over [-1, 1], on its
// own view texels (the texture's height, BakeContents::density_view_size).
vec4 skybakeMultipleDensity(float r, float mu, float mu_s, float nu) {
  ivec4 size = skybake_scattering_size;
  size.y = textureSize(skybake_multiple_density, 0).y;
  SkybakeScatteringCoord c = skybakeScatteringCoord(r, 1.0, mu_s, nu, false);
  c.u_mu = skybakeDensityCoordMu(mu, size.y);
  return skybakeSample4DOfSize(skybake_multiple_density, size, SKYBAKE_SCALE_MULTIPLE_DENSITY, c, mu_s < 0.0) *
         skybakeNightScale4D(mu_s);
}
#endif  // for skybakeDirectSegmentRadiance

// ---- irradiance (2D: u = mu_s, v = r) ----

// Row `row` of the irradiance table at the mu_s position x: linear with the
// sun above the ground's horizon, geometric below it where both texels are
// positive, the interval holding the horizon in proportion to its part
// below (TableSampler::irradianceRow; with rows on their own horizons the
// ground's horizon sits higher on the axis of a higher row).
vec4 skybakeIrradianceRow(SkybakeAxisLerp x, int row) {
  vec4 a = texelFetch(skybake_irradiance, ivec2(x.i0, row), 0);
  vec4 b = texelFetch(skybake_irradiance, ivec2(x.i1, row), 0);
  int cosine_rows = skybake_irradiance_rows.x;
  float row_r = skybakeIrradianceRowRadius(row, skybake_table_2d_size.w, skybake_radii_m.x, skybake_radii_m.y,
                                           cosine_rows);
  float horizon_mu_s =
      skybakeIrradianceSunCosine(0.0, row_r, skybake_radii_m.x, skybake_irradiance_sun.x, cosine_rows);
  float horizon_texel = skybakeMuSUnitCoord(horizon_mu_s) * float(skybake_table_2d_size.z - 1);
  float below_horizon = skybakeBelowHorizonShare(horizon_texel, x.i1);
  if (below_horizon <= 0.0) return a + (b - a) * x.w1;
  return skybakeBlendGeometricWherePositive(a, b, x.w1, below_horizon);
}

// The vertical optical depth above r over its geometric blend between the
// irradiance rows i0 and i1, in the depth channel (TableSampler::depthOverItsBlend).
float skybakeIrradianceDepthOverItsBlend(float r, int size_r, SkybakeAxisLerp y) {
  float bottom = skybake_radii_m.x;
  float top = skybake_radii_m.y;
  int k = skybake_irradiance_rows.y;
  float r_low = skybakeIrradianceRowRadius(y.i0, size_r, bottom, top, 1);
  float r_high = skybakeIrradianceRowRadius(y.i1, size_r, bottom, top, 1);
  float low = skybakeOpticalDepthToTop(r_low, 1.0)[k];
  float high = skybakeOpticalDepthToTop(r_high, 1.0)[k];
  float here = skybakeOpticalDepthToTop(clamp(r, r_low, r_high), 1.0)[k];
  if (!(low > 0.0 && high > 0.0 && here > 0.0)) return 1.0;
  float blend = exp((1.0 - y.w1) * log(low) + y.w1 * log(high));
  return clamp(here / blend, 1.0 / SKYBAKE_MAX_IRRADIANCE_DEPTH_FACTOR, SKYBAKE_MAX_IRRADIANCE_DEPTH_FACTOR);
}

// Sky irradiance on a horizontal surface at radius r: across mu_s as
// skybakeIrradianceRow, geometric in r where both rows are positive (with
// cosine rows, of the irradiance over the vertical optical depth above);
// between the last row below the top and the top, the lower row's times the
// vertical optical depth above r over that above the row
// (TableSampler::irradiance).
vec4 skybakeIrradianceTable(float r, float mu_s) {
  int size_mu_s = skybake_table_2d_size.z;
  int size_r = skybake_table_2d_size.w;
  float bottom = skybake_radii_m.x;
  float top = skybake_radii_m.y;
  int cosine_rows = skybake_irradiance_rows.x;
  float axis_mu_s = skybakeIrradianceSunCosine(mu_s, min(r, top), bottom, skybake_irradiance_sun.x, cosine_rows);
  float u = skybakeTextureCoordFromUnitRange(skybakeMuSUnitCoord(axis_mu_s), size_mu_s);
  float v = skybakeIrradianceCoordR(r, bottom, top, size_r, cosine_rows);
  SkybakeAxisLerp x = skybakeAxisLerp(u, size_mu_s);
  SkybakeAxisLerp y = skybakeAxisLerp(v, size_r);
  vec4 low = skybakeIrradianceRow(x, y.i0);
  vec4 high = skybakeIrradianceRow(x, y.i1);
  vec4 night = skybakeNightScale(mu_s);  // once: a power per channel
  if (y.i1 == size_r - 1 && y.i1 > y.i0) {
    float row_r = skybakeIrradianceRowRadius(y.i0, size_r, bottom, top, cosine_rows);
    vec4 above_r = skybakeOpticalDepthToTop(min(r, top), 1.0);
    vec4 above_row = skybakeOpticalDepthToTop(row_r, 1.0);
    // The floor keeps the discarded quotient finite where no air is above
    // the row (mix would carry a NaN through).
    vec4 thinning = mix(vec4(1.0), clamp(above_r / max(above_row, vec4(1e-30)), 0.0, 1.0),
                        vec4(greaterThan(above_row, vec4(0.0))));
    return low * thinning * night;
  }
  vec4 blend = skybakeBlendGeometricWherePositive(low, high, y.w1, 1.0);
  if (cosine_rows != 0 && y.i1 > y.i0) blend *= skybakeIrradianceDepthOverItsBlend(r, size_r, y);
  return blend * night;
}

// ---- the multiple-scattering shape f(r, nu), sr^-1 per channel ----

// Its peak weight w at an altitude: Mie's share of scattering there times
// m_column^2 (thinned by the bake file's version: multiple_scattering_phase.h).
vec4 skybakeMultiplePeakWeight(float altitude_m) {
  vec4 rayleigh = skybake_rayleigh_scattering * skybakeRayleighDensity(altitude_m);
  vec4 mie = skybake_mie_scattering * skybakeMieDensity(altitude_m);
  vec4 share = vec4(skybakeMieShare(rayleigh.x, mie.x), skybakeMieShare(rayleigh.y, mie.y),
                    skybakeMieShare(rayleigh.z, mie.z), skybakeMieShare(rayleigh.w, mie.w));
  return share * skybake_column_mie_share_power;
}

vec4 skybakeMultipleShapeWithPeak(vec4 peak_weight, float peak) {
  return vec4(skybakeMultipleShapeWithPeak(peak_weight.x, peak), skybakeMultipleShapeWithPeak(peak_weight.y, peak),
              skybakeMultipleShapeWithPeak(peak_weight.z, peak), skybakeMultipleShapeWithPeak(peak_weight.w, peak));
}

float skybakeMultiplePeak(float nu) { return skybakeCornetteShanksPhase(skybake_phase.y, skybake_phase.w, nu); }

vec4 skybakeMultipleShape(float altitude_m, float nu) {
  return skybakeMultipleShapeWithPeak(skybakeMultiplePeakWeight(altitude_m), skybakeMultiplePeak(nu));
}
