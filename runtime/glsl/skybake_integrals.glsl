// skybake GLSL library (README.md gives the files' order): integrals along a ray
// (runtime/physics/ray_quadrature.h, single_scattering_ray.cpp, segment_radiance.cpp):
// composite 4-point Gauss-Legendre rules whose optically thick sub-intervals
// are split into pieces, single scattering with the ray cut at the edges of
// the planet's shadow, and the direct integral of a segment's scattering
// sources.

struct SkybakeSingleScattering {
  vec4 rayleigh;  // without its phase function, W m^-2 nm^-1
  vec4 mie;
};

// The pieces of [a, b] that forEachOpticallyThinPiece yields, one per call
// of skybakeNextPiece: `segments` equal sub-intervals, each split into
// pieces of optical depth at most SKYBAKE_MAX_PIECE_OPTICAL_DEPTH until the
// depth from a passes SKYBAKE_REFINED_OPTICAL_DEPTH. The extinction is that
// of the most attenuated channel along the ray (r, mu).
struct SkybakePieces {
  float r, mu;      // the ray
  float a, step_m;  // start, sub-interval length
  float b;
  float lowest_t;  // the ray's lowest point
  int segments;
  int next_segment;
  float depth;             // optical depth travelled (estimate)
  float extinction_start;  // at the next sub-interval's start, m^-1
  // A sub-interval being split: its ends, piece length, pieces and the next.
  float split_start, split_end, split_step;
  int split_count, split_next;
};

float skybakeLargestExtinctionAlongRay(float r, float mu, float t) {
  return skybakeLargestChannel(skybakeExtinction(skybakeShellRadiusAlongRay(r, mu, t) - skybake_radii_m.x));
}

SkybakePieces skybakePieces(float r, float mu, float a, float b, int segments) {
  return SkybakePieces(r, mu, a, (b - a) / float(segments), b, -r * mu, segments, 0, 0.0,
                       skybakeLargestExtinctionAlongRay(r, mu, a), 0.0, 0.0, 0.0, 0, 0);
}

bool skybakeNextPiece(inout SkybakePieces p, out float piece_start, out float piece_end) {
  // Bounded: each pass yields a piece or starts a split sub-interval.
  for (int guard = 0; guard < 2 * SKYBAKE_MAX_PIECES_PER_SUBINTERVAL + 4; ++guard) {
    if (p.split_next < p.split_count) {
      piece_start = p.split_start + float(p.split_next) * p.split_step;
      if (!(p.depth < SKYBAKE_REFINED_OPTICAL_DEPTH)) {
        piece_end = p.split_end;
        p.split_count = 0;
        return true;
      }
      piece_end = p.split_next + 1 == p.split_count ? p.split_end : piece_start + p.split_step;
      p.split_next += 1;
      if (p.split_next == p.split_count) p.split_count = 0;
      p.depth += skybakeLargestExtinctionAlongRay(p.r, p.mu, 0.5 * (piece_start + piece_end)) * (piece_end - piece_start);
      return true;
    }
    if (p.next_segment >= p.segments) return false;
    int s = p.next_segment;
    p.next_segment += 1;
    float start = p.a + float(s) * p.step_m;
    float end = s + 1 == p.segments ? p.b : start + p.step_m;
    piece_start = start;
    piece_end = end;
    if (!(p.depth < SKYBAKE_REFINED_OPTICAL_DEPTH)) return true;
    float extinction_end = skybakeLargestExtinctionAlongRay(p.r, p.mu, end);
    float peak = max(max(p.extinction_start, skybakeLargestExtinctionAlongRay(p.r, p.mu, 0.5 * (start + end))),
                     extinction_end);
    if (p.lowest_t > start && p.lowest_t < end)
      peak = max(peak, skybakeLargestExtinctionAlongRay(p.r, p.mu, p.lowest_t));
    p.extinction_start = extinction_end;
    float piece_depth = peak * (end - start);
    if (!(piece_depth > SKYBAKE_MAX_PIECE_OPTICAL_DEPTH && !isinf(peak))) {
      p.depth += piece_depth;
      return true;
    }
    p.split_count = int(min(float(SKYBAKE_MAX_PIECES_PER_SUBINTERVAL), ceil(piece_depth / SKYBAKE_MAX_PIECE_OPTICAL_DEPTH)));
    p.split_next = 0;
    p.split_start = start;
    p.split_end = end;
    p.split_step = (end - start) / float(p.split_count);
  }
  return false;
}

// The 4-point rule's nodes and weights as vectors, entry k read without
// indexing an array by k: a shader compiler unrolls every loop that indexes
// a local array by its counter (Mesa does, to keep the array in registers),
// which would copy the node loop's body, three optical-depth lookups, once
// per node.
#if SKYBAKE_GAUSS_NODES != 4
#error "skybakeGaussEntry reads a 4-point rule"
#endif
vec4 skybakeGaussVector(float entries[SKYBAKE_GAUSS_NODES]) {
  return vec4(entries[0], entries[1], entries[2], entries[3]);
}

float skybakeGaussEntry(vec4 entries, int k) { return dot(entries, vec4(equal(ivec4(0, 1, 2, 3), ivec4(k)))); }

// Single scattering at the 4-point rule's nodes over [a, b] of the ray
// (r, mu) with the sun at (mu_s, nu), in pass g's lanes
// (skybakePassOpticalDepthToTop; start_to_top_up and _down the ray's own
// legs to the top in it), added to rayleigh and mie without the factors
// common to every node (the pass's weights); with a moon (an eclipse) also
// to rayleigh_past_moon and mie_past_moon with the sunlight at each node
// dimmed by the part of the disk the moon hides there.
void skybakeAddSingleScatteringPart(float r, float mu, float mu_s, float nu, bool ray_intersects_ground, int g,
                                    vec4 start_to_top_up, vec4 start_to_top_down, float a, float b,
                                    SkybakeMoonAlongRay moon, inout vec4 rayleigh, inout vec4 mie,
                                    inout vec4 rayleigh_past_moon, inout vec4 mie_past_moon) {
  float bottom = skybake_radii_m.x;
  vec4 gauss_abscissa = skybakeGaussVector(SKYBAKE_GAUSS_ABSCISSA);
  vec4 gauss_weight = skybakeGaussVector(SKYBAKE_GAUSS_WEIGHT);
  float h = b - a;
  for (int k = 0; k < SKYBAKE_GAUSS_NODES; ++k) {
    float t = a + 0.5 * h * (1.0 + skybakeGaussEntry(gauss_abscissa, k));
    float w = 0.5 * h * skybakeGaussEntry(gauss_weight, k);
    float r_t = skybakeShellRadiusAlongRay(r, mu, t);
    float altitude_m = r_t - bottom;
    float mu_s_t = skybakeClampCosine((r * mu_s + t * nu) / r_t);
    float visible = skybakeSunDiskVisibleFraction(mu_s_t - skybakeTangentZenithCosine(r_t, bottom),
                                                  skybakeSunDiskHalfSizeAtHorizon(bottom, r_t, skybake_sun_disk.x));
    // Nothing where the node is in the planet's shadow (an if, not a
    // continue: llvmpipe mishandles continue in loops nested this deep).
    if (visible > 0.0) {
      // The sunlight's whole path in one exponential: to the node, then on to
      // the ray's start.
      float mu_t = skybakeCosineAlongRay(r, mu, t, r_t);
      bool reversed = ray_intersects_ground || t <= -r * mu;
      vec4 along = reversed ? max(skybakePassOpticalDepthToTop(g, r_t, -mu_t) - start_to_top_down, vec4(0.0))
                            : max(start_to_top_up - skybakePassOpticalDepthToTop(g, r_t, mu_t), vec4(0.0));
      vec4 light = exp(-(skybakePassOpticalDepthToTop(g, r_t, mu_s_t) + along)) * visible;
      vec4 rayleigh_term = light * (w * skybakeRayleighDensity(altitude_m));
      vec4 mie_term = light * (w * skybakeMieDensity(altitude_m));
      rayleigh += rayleigh_term;
      mie += mie_term;
      if (moon.moon.radius_m > 0.0) {
        float past_moon = skybakeMoonVisibleSunFractionAt(moon, t);
        rayleigh_past_moon += rayleigh_term * past_moon;
        mie_past_moon += mie_term * past_moon;
      }
    }
  }
}

// Single scattering of one ray without the moon (`plain`) and with it
// (`past_moon`), integrated at the same nodes.
struct SkybakeSingleScatteringPastMoon {
  SkybakeSingleScattering plain;
  SkybakeSingleScattering past_moon;
};

// Pass g's lanes of Rayleigh and Mie single scattering in the channels
// (skybake_pass_*_weights: row c of a pass's weights is what each of its
// lanes adds to channel c).
vec4 skybakePassRayleigh(int g, vec4 lanes) {
  return vec4(dot(skybake_pass_rayleigh_weights[4 * g], lanes), dot(skybake_pass_rayleigh_weights[4 * g + 1], lanes),
              dot(skybake_pass_rayleigh_weights[4 * g + 2], lanes), dot(skybake_pass_rayleigh_weights[4 * g + 3], lanes));
}

vec4 skybakePassMie(int g, vec4 lanes) {
  return vec4(dot(skybake_pass_mie_weights[4 * g], lanes), dot(skybake_pass_mie_weights[4 * g + 1], lanes),
              dot(skybake_pass_mie_weights[4 * g + 2], lanes), dot(skybake_pass_mie_weights[4 * g + 3], lanes));
}

// Single scattering over [t_start, t_end] of the ray (r, mu) with the sun at
// (mu_s, nu), seen from the ray's start; `segments` sub-intervals over the
// whole of it, each cut where the ray crosses the edge of the planet's
// shadow (integrateSingleScattering, forEachOpticallyThinNodeCutAt). With a
// moon (an eclipse; its origin, dir and sun_dir the 3D form of the ray) the
// same integral with the moon's shadow too, at the same nodes: one pass for
// what the C++ integrates twice, since llvmpipe ends a shader's loops after
// 65535 iterations in all.
SkybakeSingleScatteringPastMoon skybakeIntegrateSingleScattering(float r, float mu, float mu_s, float nu,
                                                                 bool ray_intersects_ground, float t_start,
                                                                 float t_end, int segments,
                                                                 SkybakeMoonAlongRay moon) {
  SkybakeSingleScattering none = SkybakeSingleScattering(vec4(0.0), vec4(0.0));
  // A light shaft's shadow can reach past the ray's end: nothing is lit.
  if (!(t_end > t_start)) return SkybakeSingleScatteringPastMoon(none, none);
  SkybakeSingleScatteringPastMoon sums = SkybakeSingleScatteringPastMoon(none, none);
  SkybakeShadowCrossings crossings = skybakePlanetShadowCrossings(r, mu, mu_s, nu, t_end);
  // One pass over the ray per wavelength group of a colour bake (the same
  // nodes each time), one for any other bake, each pass's sums weighted
  // into the channels as it ends (the weights are linear, the same at every
  // node). The pass count is uniform, so the weights' rows are read once.
  for (int g = 0; g < skybake_integral_passes.x; ++g) {
    vec4 rayleigh = vec4(0.0);
    vec4 mie = vec4(0.0);
    vec4 rayleigh_past_moon = vec4(0.0);
    vec4 mie_past_moon = vec4(0.0);
    // The ray's own legs to the top, the same at every node of the pass.
    vec4 start_to_top_up = skybakePassOpticalDepthToTop(g, r, mu);
    vec4 start_to_top_down = skybakePassOpticalDepthToTop(g, r, -mu);
    SkybakePieces pieces = skybakePieces(r, mu, t_start, t_end, segments);
    // The pieces (skybakeNextPiece) cut at the shadow's crossings into
    // parts, one part per iteration (the next piece fetched first where the
    // last is done): llvmpipe counts every loop's iterations against one
    // limit (65535 per shader run), which an eclipse's irradiance, 48 such
    // integrals and its kernel, comes near; a loop of parts inside a loop
    // of pieces cost it three iterations per piece.
    float a = t_start;
    float b = t_start;
    float part_start = t_start;
    while (true) {
      if (!(part_start < b)) {
        if (!skybakeNextPiece(pieces, a, b)) break;
        part_start = a;
      }
      // Up to the first crossing inside the piece's rest, or its end; one
      // call site, so that shader compilers inline the rule once.
      float part_end = b;
      if (crossings.count > 0 && crossings.distance_m.x > part_start && crossings.distance_m.x < part_end)
        part_end = crossings.distance_m.x;
      if (crossings.count > 1 && crossings.distance_m.y > part_start && crossings.distance_m.y < part_end)
        part_end = crossings.distance_m.y;
      skybakeAddSingleScatteringPart(r, mu, mu_s, nu, ray_intersects_ground, g, start_to_top_up, start_to_top_down,
                                     part_start, part_end, moon, rayleigh, mie, rayleigh_past_moon, mie_past_moon);
      part_start = part_end;
    }
    sums.plain.rayleigh += skybakePassRayleigh(g, rayleigh);
    sums.plain.mie += skybakePassMie(g, mie);
    sums.past_moon.rayleigh += skybakePassRayleigh(g, rayleigh_past_moon);
    sums.past_moon.mie += skybakePassMie(g, mie_past_moon);
  }
  return sums;
}

// The same without a moon.
SkybakeSingleScattering skybakeIntegrateSingleScattering(float r, float mu, float mu_s, float nu,
                                                         bool ray_intersects_ground, float t_start, float t_end,
                                                         int segments) {
  SkybakeMoonAlongRay none = SkybakeMoonAlongRay(skybakeNoMoon(), vec3(0.0), vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0));
  return skybakeIntegrateSingleScattering(r, mu, mu_s, nu, ray_intersects_ground, t_start, t_end, segments, none)
      .plain;
}

// Needed by the radiance to points and by ground rays where the table
// holds none (SKYBAKE_NO_RADIANCE_TO_POINT, SKYBAKE_BAKE_HAS_GROUND_VIEWS).
#if !defined(SKYBAKE_NO_RADIANCE_TO_POINT) || !defined(SKYBAKE_BAKE_HAS_GROUND_VIEWS)
// In-scattered radiance over [0, length_m] of the ray (r, mu) with the sun
// at (mu_s, nu), each source attenuated back to the start, and the
// segment's transmittance, the optical depth integrated from the density
// profiles (directSegmentRadiance). `with_single` false leaves single
// scattering out.
SkybakeRadianceAndTransmittance skybakeDirectSegmentRadiance(float r, float mu, float mu_s, float nu, float length_m,
                                                             int subintervals, bool with_single) {
  float bottom = skybake_radii_m.x;
  float rayleigh_phase = skybakeRayleighPhase(nu);
  float mie_phase = skybakeMiePhase(nu);
  float multiple_peak = skybakeMultiplePeak(nu);
  float gauss_abscissa[SKYBAKE_GAUSS_NODES] = SKYBAKE_GAUSS_ABSCISSA;
  float gauss_weight[SKYBAKE_GAUSS_NODES] = SKYBAKE_GAUSS_WEIGHT;
  vec4 sum = vec4(0.0);
  vec4 before = vec4(0.0);  // optical depth from 0 to the current piece
  SkybakePieces pieces = skybakePieces(r, mu, 0.0, length_m, subintervals);
  float a, b;
  while (skybakeNextPiece(pieces, a, b)) {
    float h = b - a;
    vec4 whole = vec4(0.0);
    for (int k = 0; k < SKYBAKE_GAUSS_NODES; ++k) {
      float d = a + 0.5 * h * (1.0 + gauss_abscissa[k]);
      float partial_length_m = d - a;
      vec4 partial = vec4(0.0);
      for (int j = 0; j < SKYBAKE_GAUSS_NODES; ++j) {
        float t = a + 0.5 * partial_length_m * (1.0 + gauss_abscissa[j]);
        partial += skybakeExtinction(skybakeShellRadiusAlongRay(r, mu, t) - bottom) *
                   (0.5 * partial_length_m * gauss_weight[j]);
      }
      float w = 0.5 * h * gauss_weight[k];
      float r_d = skybakeShellRadiusAlongRay(r, mu, d);
      float altitude_m = r_d - bottom;
      whole += skybakeExtinction(altitude_m) * w;
      float mu_d = skybakeCosineAlongRay(r, mu, d, r_d);
      float mu_s_d = skybakeClampCosine((r * mu_s + d * nu) / r_d);
      vec4 single_source = vec4(0.0);
      if (with_single) {
        single_source = (skybake_rayleigh_scattering * (skybakeRayleighDensity(altitude_m) * rayleigh_phase) +
                         skybake_mie_scattering * (skybakeMieDensity(altitude_m) * mie_phase)) *
                        (skybake_sun_irradiance * skybakeTransmittanceToSun(r_d, mu_s_d));
      }
      vec4 multiple_source = skybakeMultipleDensity(r_d, mu_d, mu_s_d, nu) *
                             skybakeMultipleShapeWithPeak(skybakeMultiplePeakWeight(altitude_m), multiple_peak);
      sum += (single_source + multiple_source) * exp(-(before + partial)) * w;
    }
    before += whole;
  }
  return SkybakeRadianceAndTransmittance(sum, exp(-before));
}
#endif
