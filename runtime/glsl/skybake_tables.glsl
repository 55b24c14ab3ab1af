// skybake GLSL library (README.md gives the files' order): where a configuration lives in the
// tables (data_formats/texture_mapping.h) and the interpolated lookups
// (runtime/table_sampler.h), the multiple-scattering shape
// (runtime/multiple_scattering_phase.h) included.
//
// Interpolation is done here from texelFetch with the CPU's weights:
// hardware filtering resolves the weights to 8 bits (1/256 of a texel), a
// quantisation that shows as bands where tables change steeply (the
// horizon, twilight), and it cannot do the geometric blends below.

// [0, 1] -> texture coordinate whose texel centres hit 0 and 1 exactly.
float skybakeTextureCoordFromUnitRange(float x, int size) {
  return 0.5 / float(size) + x * (1.0 - 1.0 / float(size));
}
float skybakeFractionOfRange(float value, float lo, float hi) { return hi > lo ? (value - lo) / (hi - lo) : 0.0; }

// Linear interpolation on an axis of `size` texels: the two neighbours and
// the weight of the upper one.
struct SkybakeAxisLerp {
  int i0;
  int i1;
  float w1;
};

// Positions outside the axis clamp to its ends (a NaN position to the first).
float skybakeClampedAxisPosition(float x, int size) { return x > 0.0 ? min(x, float(size - 1)) : 0.0; }

SkybakeAxisLerp skybakeAxisLerp(float u, int size) {
  float x = skybakeClampedAxisPosition(u * float(size) - 0.5, size);
  int i0 = min(int(x), max(size - 2, 0));
  return SkybakeAxisLerp(i0, min(i0 + 1, size - 1), x - float(i0));
}

// nu texels sit at i / (size - 1): both ends tabulated.
SkybakeAxisLerp skybakeAxisLerpNu(float u_nu, int size) {
  float x = skybakeClampedAxisPosition(u_nu * float(size - 1), size);
  int i0 = min(int(x), size - 2);
  return SkybakeAxisLerp(i0, i0 + 1, x - float(i0));
}

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

// a^(1-w) b^w per channel where both are positive and more than
// SKYBAKE_FULLY_GEOMETRIC_BLEND_RATIO apart, linear where they are within
// SKYBAKE_GEOMETRIC_BLEND_RATIO, moving smoothly from one to the other
// between: exact for the exponential falloff of a twilight sky across mu_s
// and nu, and without a jump as the ratio changes (table_sampler.h).
vec4 skybakeBlendGeometricWhereSteep(vec4 a, vec4 b, float w) {
  vec4 linear_blend = a + (b - a) * w;
  bvec4 positive = bvec4(vec4(greaterThan(a, vec4(0.0))) * vec4(greaterThan(b, vec4(0.0))));
  bvec4 apart = bvec4(max(vec4(greaterThan(b, SKYBAKE_GEOMETRIC_BLEND_RATIO * a)),
                          vec4(greaterThan(a, SKYBAKE_GEOMETRIC_BLEND_RATIO * b))));
  bvec4 steep = bvec4(vec4(positive) * vec4(apart));
  // Logarithms of 1 where the blend is linear, so no log(0) is taken.
  vec4 safe_a = mix(vec4(1.0), a, steep);
  vec4 safe_b = mix(vec4(1.0), b, steep);
  vec4 ratio = max(safe_a / safe_b, safe_b / safe_a);
  vec4 share = smoothstep(vec4(SKYBAKE_GEOMETRIC_BLEND_RATIO), vec4(SKYBAKE_FULLY_GEOMETRIC_BLEND_RATIO), ratio);
  return mix(linear_blend, exp((1.0 - w) * log(safe_a) + w * log(safe_b)), share * vec4(steep));
}

vec4 skybakeBlendAcross(vec4 a, vec4 b, float w, bool geometric) {
  return geometric ? skybakeBlendGeometricWhereSteep(a, b, w) : a + (b - a) * w;
}

// The 4D tables' texel (r, mu, mu_s, nu), before its slice's scale.
vec4 skybakeTexel4D(sampler3D table, int i_r, int i_mu, int i_mu_s, int i_nu) {
  return texelFetch(table, ivec3(i_nu * skybake_scattering_size.z + i_mu_s, i_mu, i_r), 0);
}

// The scales of the four (r, mu_s) slices around a lookup, lane `scale` of
// skybake_slice_scales: x (r0, mu_s0), y (r0, mu_s1), z (r1, mu_s0), w (r1, mu_s1).
vec4 skybakeSliceScales(int scale, SkybakeAxisLerp r, SkybakeAxisLerp mu_s) {
  return vec4(texelFetch(skybake_slice_scales, ivec2(mu_s.i0, r.i0), 0)[scale],
              texelFetch(skybake_slice_scales, ivec2(mu_s.i1, r.i0), 0)[scale],
              texelFetch(skybake_slice_scales, ivec2(mu_s.i0, r.i1), 0)[scale],
              texelFetch(skybake_slice_scales, ivec2(mu_s.i1, r.i1), 0)[scale]);
}

// Trilinear in (mu_s, mu, r) within one nu slice, mu_s blended geometrically
// where `geometric` says; `scales` from skybakeSliceScales.
vec4 skybakeSampleNuSlice(sampler3D table, vec4 scales, SkybakeAxisLerp r, SkybakeAxisLerp mu, SkybakeAxisLerp mu_s,
                          int i_nu, bool geometric) {
  vec4 r0mu0 = skybakeBlendAcross(skybakeTexel4D(table, r.i0, mu.i0, mu_s.i0, i_nu) * scales.x,
                                  skybakeTexel4D(table, r.i0, mu.i0, mu_s.i1, i_nu) * scales.y, mu_s.w1, geometric);
  vec4 r0mu1 = skybakeBlendAcross(skybakeTexel4D(table, r.i0, mu.i1, mu_s.i0, i_nu) * scales.x,
                                  skybakeTexel4D(table, r.i0, mu.i1, mu_s.i1, i_nu) * scales.y, mu_s.w1, geometric);
  vec4 r1mu0 = skybakeBlendAcross(skybakeTexel4D(table, r.i1, mu.i0, mu_s.i0, i_nu) * scales.z,
                                  skybakeTexel4D(table, r.i1, mu.i0, mu_s.i1, i_nu) * scales.w, mu_s.w1, geometric);
  vec4 r1mu1 = skybakeBlendAcross(skybakeTexel4D(table, r.i1, mu.i1, mu_s.i0, i_nu) * scales.z,
                                  skybakeTexel4D(table, r.i1, mu.i1, mu_s.i1, i_nu) * scales.w, mu_s.w1, geometric);
  vec4 r0 = r0mu0 + (r0mu1 - r0mu0) * mu.w1;
  vec4 r1 = r1mu0 + (r1mu1 - r1mu0) * mu.w1;
  return r0 + (r1 - r0) * r.w1;
}

// A 4D table's texture coordinates (texture_mapping.h, ScatteringCoord).
struct SkybakeScatteringCoord {
  float u_nu;
  float u_mu_s;
  float u_mu;
  float u_r;
};

// A 4D table of `size` texels (r, mu, mu_s, nu), `scale` its SKYBAKE_SCALE_*
// lane, at texture coordinates `c`.
vec4 skybakeSample4DOfSize(sampler3D table, ivec4 size, int scale, SkybakeScatteringCoord c, bool geometric) {
  SkybakeAxisLerp r = skybakeAxisLerp(c.u_r, size.x);
  SkybakeAxisLerp mu = skybakeAxisLerp(c.u_mu, size.y);
  SkybakeAxisLerp mu_s = skybakeAxisLerp(c.u_mu_s, size.z);
  SkybakeAxisLerp nu = skybakeAxisLerpNu(c.u_nu, size.w);
  vec4 scales = skybakeSliceScales(scale, r, mu_s);
  return skybakeBlendAcross(skybakeSampleNuSlice(table, scales, r, mu, mu_s, nu.i0, geometric),
                            skybakeSampleNuSlice(table, scales, r, mu, mu_s, nu.i1, geometric), nu.w1, geometric);
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
                                skybakeAxisLerp(skybakeTextureCoordFromUnitRange(rho / H, size_r), size_r));
}

float skybakeOpticalDepthMuCoord(SkybakeOpticalDepthAtR at, float mu) {
  float dist = skybakeDistanceToOuterSphere(at.r, mu, skybake_radii_m.y);
  return skybakeTextureCoordFromUnitRange(skybakeFractionOfRange(dist, at.dist_min_m, at.dist_max_m),
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
// (MuSUnitCoordMap, SunBelowHorizonAxis).
float skybakeMuSUnitCoord(float mu_s) {
  vec4 m = skybake_mu_s_map;
  vec4 below = skybake_mu_s_below;
  float a = (skybakeDistanceToOuterSphere(skybake_radii_m.x, mu_s, skybake_radii_m.y) - m.x) * m.y;
  float bruneton = m.w * max(1.0 - a * m.z, 0.0) / (1.0 + a);
  if (below.x == 0.0) return bruneton;
  if (mu_s >= 0.0) return below.x + (1.0 - below.x) * (bruneton - below.y) / (1.0 - below.y);
  float t = min(mu_s * below.z, 1.0);
  float c = below.w;
  return below.x * (1.0 - 2.0 * t / (c + sqrt(c * c + 4.0 * (1.0 - c) * t)));
}

SkybakeScatteringCoord skybakeScatteringCoord(float r, float mu, float mu_s, float nu, bool ray_intersects_ground) {
  float bottom = skybake_radii_m.x;
  float top = skybake_radii_m.y;
  float H = skybake_radii_m.z;
  ivec4 size = skybake_scattering_size;
  float rho = skybakeDistanceToHorizon(r);
  float u_mu;
  if (skybake_parts.x == 0) {
    // Sky only over the whole axis; a ray to the ground is read at the horizon.
    float dist = ray_intersects_ground ? rho + H : skybakeDistanceToOuterSphere(r, mu, top);
    u_mu = skybakeTextureCoordFromUnitRange(skybakeFractionOfRange(dist, top - r, rho + H), size.y);
  } else if (ray_intersects_ground) {
    // Distance to the ground, between r - bottom (straight down) and rho.
    float dist = skybakeDistanceToInnerSphere(r, mu, bottom);
    u_mu = 0.5 - 0.5 * skybakeTextureCoordFromUnitRange(skybakeFractionOfRange(dist, r - bottom, rho), size.y / 2);
  } else {
    // Distance to the top, between top - r (straight up) and rho + H.
    float dist = skybakeDistanceToOuterSphere(r, mu, top);
    u_mu = 0.5 + 0.5 * skybakeTextureCoordFromUnitRange(skybakeFractionOfRange(dist, top - r, rho + H), size.y / 2);
  }
  vec4 domain = skybake_scattering_domain;
  float u_mu_s = skybakeTextureCoordFromUnitRange((skybakeMuSUnitCoord(mu_s) - domain.z) * domain.w, size.z);
  float u_r = skybakeTextureCoordFromUnitRange(skybakeFractionOfRange(rho, domain.x, domain.y), size.x);
  return SkybakeScatteringCoord((nu + 1.0) * 0.5, u_mu_s, u_mu, u_r);
}

// ---- the night continuation (runtime/night_sky.h) ----

// The share of the lowest baked sun's tabulated light left with the sun at
// zenith cosine mu_s: 1 at and above it, (1 - tan(d / 2) / tan(span / 2))^p
// at depression d below, 0 from the dark angle on
// (NightContinuation::scaleBelowEdge; no acos, see there).
vec4 skybakeNightScale(float mu_s) {
  if (mu_s >= skybake_night.x) return vec4(1.0);
  mu_s = clamp(mu_s, -1.0, 1.0);
  float sin_s = sqrt(max(1.0 - mu_s * mu_s, 0.0));
  float sin_d = sin_s * skybake_night.x - mu_s * skybake_night.y;
  float cos_d = mu_s * skybake_night.x + sin_s * skybake_night.y;
  float x = clamp(1.0 - sin_d / (1.0 + cos_d) * skybake_night.z, 0.0, 1.0);
  return pow(vec4(x), skybake_night_exponent);  // p >= 1: pow(0, p) is defined
}

// For the 4D tables (TableSampler::nightScale4D): a narrowed scene's tables
// are clamped to its lowest sun instead.
vec4 skybakeNightScale4D(float mu_s) { return skybake_night.w > 0.5 ? skybakeNightScale(mu_s) : vec4(1.0); }

// A radiance table at (r, mu, mu_s, nu): geometric blends across mu_s and nu
// with the sun below the horizon (radianceBlend).
// `scale`: the table's SKYBAKE_SCALE_* lane.
vec4 skybakeScattering(sampler3D table, int scale, float r, float mu, float mu_s, float nu, bool ray_intersects_ground) {
  return skybakeSample4D(table, scale, skybakeScatteringCoord(r, mu, mu_s, nu, ray_intersects_ground), mu_s < 0.0) *
         skybakeNightScale4D(mu_s);
}

// The multiple-scattering density table: mu linear over [-1, 1], on its
// own view texels (the texture's height, BakeContents::density_view_size).
vec4 skybakeMultipleDensity(float r, float mu, float mu_s, float nu) {
  ivec4 size = skybake_scattering_size;
  size.y = textureSize(skybake_multiple_density, 0).y;
  SkybakeScatteringCoord c = skybakeScatteringCoord(r, 1.0, mu_s, nu, false);
  c.u_mu = skybakeTextureCoordFromUnitRange((mu + 1.0) * 0.5, size.y);
  return skybakeSample4DOfSize(skybake_multiple_density, size, SKYBAKE_SCALE_MULTIPLE_DENSITY, c, mu_s < 0.0) *
         skybakeNightScale4D(mu_s);
}

// ---- irradiance (2D: u = mu_s, v = r) ----

// Row `row` of the irradiance table at the mu_s position x: linear with the
// sun above the horizon, geometric below it where both texels are positive,
// the interval holding the horizon in proportion to its part below
// (TableSampler::irradianceRow).
vec4 skybakeIrradianceRow(SkybakeAxisLerp x, int row) {
  vec4 a = texelFetch(skybake_irradiance, ivec2(x.i0, row), 0);
  vec4 b = texelFetch(skybake_irradiance, ivec2(x.i1, row), 0);
  vec4 linear_blend = a + (b - a) * x.w1;
  float horizon_texel = skybakeMuSUnitCoord(0.0) * float(skybake_table_2d_size.z - 1);
  float below_horizon = clamp(1.0 + horizon_texel - float(x.i1), 0.0, 1.0);
  bvec4 positive = bvec4(vec4(greaterThan(a, vec4(0.0))) * vec4(greaterThan(b, vec4(0.0))));
  // Logarithms of 1 where a texel is 0, so no log(0) is taken.
  vec4 safe_a = mix(vec4(1.0), a, positive);
  vec4 safe_b = mix(vec4(1.0), b, positive);
  vec4 geometric = exp((1.0 - x.w1) * log(safe_a) + x.w1 * log(safe_b));
  return mix(linear_blend, geometric, below_horizon * vec4(positive));
}

// Sky irradiance on a horizontal surface at radius r: across mu_s as
// skybakeIrradianceRow, geometric in r where both rows are positive; between
// the last row below the top and the top, the lower row's times the
// vertical optical depth above r over that above the row
// (TableSampler::irradiance).
vec4 skybakeIrradianceTable(float r, float mu_s) {
  int size_mu_s = skybake_table_2d_size.z;
  int size_r = skybake_table_2d_size.w;
  float bottom = skybake_radii_m.x;
  float top = skybake_radii_m.y;
  float u = skybakeTextureCoordFromUnitRange(skybakeMuSUnitCoord(mu_s), size_mu_s);
  float v = skybakeTextureCoordFromUnitRange((r - bottom) / (top - bottom), size_r);
  SkybakeAxisLerp x = skybakeAxisLerp(u, size_mu_s);
  SkybakeAxisLerp y = skybakeAxisLerp(v, size_r);
  vec4 low = skybakeIrradianceRow(x, y.i0);
  if (y.i1 == size_r - 1 && y.i1 > y.i0) {
    float row_r = bottom + float(y.i0) / float(size_r - 1) * (top - bottom);
    vec4 above_r = skybakeOpticalDepthToTop(min(r, top), 1.0);
    vec4 above_row = skybakeOpticalDepthToTop(row_r, 1.0);
    // The floor keeps the discarded quotient finite where no air is above
    // the row (mix would carry a NaN through).
    vec4 thinning = mix(vec4(1.0), clamp(above_r / max(above_row, vec4(1e-30)), 0.0, 1.0),
                        vec4(greaterThan(above_row, vec4(0.0))));
    return low * thinning * skybakeNightScale(mu_s);
  }
  vec4 high = skybakeIrradianceRow(x, y.i1);
  bvec4 positive = bvec4(vec4(greaterThan(low, vec4(0.0))) * vec4(greaterThan(high, vec4(0.0))));
  vec4 safe_low = mix(vec4(1.0), low, positive);
  vec4 safe_high = mix(vec4(1.0), high, positive);
  return mix(low + (high - low) * y.w1, exp((1.0 - y.w1) * log(safe_low) + y.w1 * log(safe_high)), positive) *
         skybakeNightScale(mu_s);
}

// ---- the multiple-scattering shape f(r, nu), sr^-1 per channel ----

// Its peak weight w at an altitude: Mie's share of scattering there times
// m_column^2.
vec4 skybakeMultiplePeakWeight(float altitude_m) {
  vec4 rayleigh = skybake_rayleigh_scattering * skybakeRayleighDensity(altitude_m);
  vec4 mie = skybake_mie_scattering * skybakeMieDensity(altitude_m);
  vec4 total = rayleigh + mie;
  bvec4 scatters = greaterThan(total, vec4(0.0));
  // 0 where nothing scatters (any positive divisor will do there).
  vec4 share = mix(vec4(0.0), mie / mix(vec4(1.0), total, scatters), scatters);
  return share * skybake_column_mie_share_power;
}

vec4 skybakeMultipleShapeWithPeak(vec4 peak_weight, float peak) {
  return vec4(SKYBAKE_BROAD_PHASE) + peak_weight * (peak - SKYBAKE_BROAD_PHASE);
}

float skybakeMultiplePeak(float nu) { return skybakeCornetteShanksPhase(skybake_phase.y, skybake_phase.w, nu); }

vec4 skybakeMultipleShape(float altitude_m, float nu) {
  return skybakeMultipleShapeWithPeak(skybakeMultiplePeakWeight(altitude_m), skybakeMultiplePeak(nu));
}
