// Kernel (kernel_language.h): where a configuration (r, mu, mu_s, nu)
// lives in the tables, the forward maps of the parameterization that
// data_formats/parameterization/texture_mapping.h describes. The bake (reading earlier
// scattering orders), the CPU lookups and the shaders all place a lookup
// with these; the inverse maps (texel -> configuration) only the bake needs,
// and they stay in texture_mapping.cpp.

// [0, 1] -> texture coordinate whose texel centres hit 0 and 1 exactly.
SKYBAKE_KERNEL Real skybakeTextureCoordFromUnitRange(Real x, int size) {
  return 0.5 / Real(size) + x * (1.0 - 1.0 / Real(size));
}

// The position of value in [lo, hi]; 0 where the range is a point (r =
// bottom in a ground half, r = top in a sky half), which guards 0 / 0.
SKYBAKE_KERNEL Real skybakeFractionOfRange(Real value, Real lo, Real hi) {
  return hi > lo ? (value - lo) / (hi - lo) : 0.0;
}

// ---- the optical-depth table (2D: u = mu, v = r) ----

// The mu coordinate at radius r: the distance to the top between
// dist_min_m (straight up, top - r) and dist_max_m (toward the horizon,
// rho + H).
SKYBAKE_KERNEL Real skybakeOpticalDepthCoordMuAtDistance(Real dist_to_top_m, Real dist_min_m, Real dist_max_m,
                                                         int size_mu) {
  return skybakeTextureCoordFromUnitRange(skybakeFractionOfRange(dist_to_top_m, dist_min_m, dist_max_m), size_mu);
}
SKYBAKE_KERNEL Real skybakeOpticalDepthCoordMu(Real r, Real mu, Real top_radius_m, Real dist_min_m, Real dist_max_m,
                                               int size_mu) {
  return skybakeOpticalDepthCoordMuAtDistance(skybakeDistanceToOuterSphere(r, mu, top_radius_m), dist_min_m,
                                              dist_max_m, size_mu);
}

// The r coordinate from rho, the distance to the horizon, over H, the
// distance from the ground to the top along the horizontal.
SKYBAKE_KERNEL Real skybakeOpticalDepthCoordR(Real rho_m, Real H_m, int size_r) {
  return skybakeTextureCoordFromUnitRange(rho_m / H_m, size_r);
}

// ---- the sun axis (4D tables and irradiance) ----

// The sun axis's constants for one domain (MuSUnitCoordMap::of works them
// out; the shaders read them from the uniform block's mu_s_map and
// mu_s_below).
struct SkybakeSunCoordMap {
  Real bottom_radius_m;
  Real top_radius_m;
  // Bruneton's coordinate over the distance a from the ground to the top
  // toward the sun: a = (distance - d_min) * inverse_d_span, 1 / A its
  // value at the lowest sun, `defined` 0 where the sun range is empty
  // (A = 0: every coordinate 0 then), else 1.
  Real d_min;
  Real inverse_d_span;
  Real inverse_A;
  Real defined;
  // The share of the axis below the horizon (0: Bruneton's coordinate
  // alone), Bruneton's coordinate at the horizon, 1 / mu_s_min, and the
  // below-horizon axis's spacing c at the horizon.
  Real below_share;
  Real day_coord_at_horizon;
  Real inverse_mu_s_min;
  Real horizon_spacing;
};

// The depth s in [0, 1] below the horizon of a sun whose depression's sine
// is the fraction t of the lowest sun's, from t = c s + (1 - c) s^2: the
// root written so that it stays exact as c -> 1.
SKYBAKE_KERNEL Real skybakeSunDepthFromSine(Real t, Real c) {
  return 2.0 * t / (c + sqrt(c * c + 4.0 * (1.0 - c) * t));
}

// The unit sun coordinate: 1 at the zenith, 0 at the lowest sun.
SKYBAKE_KERNEL Real skybakeSunUnitCoord(SkybakeSunCoordMap m, Real mu_s) {
  if (m.below_share > 0.0 && mu_s < 0.0) {
    return m.below_share *
           (1.0 - skybakeSunDepthFromSine(min(mu_s * m.inverse_mu_s_min, 1.0), m.horizon_spacing));
  }
  Real a = (skybakeDistanceToOuterSphere(m.bottom_radius_m, mu_s, m.top_radius_m) - m.d_min) * m.inverse_d_span;
  Real bruneton = m.defined * max(1.0 - a * m.inverse_A, 0.0) / (1.0 + a);
  if (m.below_share == 0.0) return bruneton;
  return m.below_share +
         (1.0 - m.below_share) * (bruneton - m.day_coord_at_horizon) / (1.0 - m.day_coord_at_horizon);
}

// The 4D tables' mu_s coordinate: the unit coordinate over their sun range
// [coord_min, coord_min + 1 / inverse_coord_span] (inverse_coord_span 0
// where the range is a point).
SKYBAKE_KERNEL Real skybakeScatteringCoordMuS(Real unit_coord, Real coord_min, Real inverse_coord_span,
                                              int size_mu_s) {
  return skybakeTextureCoordFromUnitRange((unit_coord - coord_min) * inverse_coord_span, size_mu_s);
}

// ---- the 4D tables' r and mu ----

// The r coordinate: rho over the tables' range of it.
SKYBAKE_KERNEL Real skybakeScatteringCoordR(Real rho_m, Real rho_min_m, Real rho_max_m, int size_r) {
  return skybakeTextureCoordFromUnitRange(skybakeFractionOfRange(rho_m, rho_min_m, rho_max_m), size_r);
}

// The mu coordinate of a ray from r that ends after dist_m, on the ground
// or at the top as ray_intersects_ground says. With ground views the
// axis's lower half holds the rays that end on the ground, by their
// distance to it between r - bottom (straight down) and rho (the horizon),
// and the upper half the others, by their distance to the top between
// top - r (straight up) and rho + H, so that no lookup interpolates across
// the horizon. Without them the sky takes the whole axis and a ray to the
// ground is read at the horizon (dist_m is not read then).
SKYBAKE_KERNEL Real skybakeScatteringCoordMuAtDistance(Real r, Real dist_m, Real bottom_radius_m, Real top_radius_m,
                                                       Real rho_m, Real H_m, int size_mu, bool ground_views,
                                                       bool ray_intersects_ground) {
  if (!ground_views) {
    Real dist = ray_intersects_ground ? rho_m + H_m : dist_m;
    return skybakeTextureCoordFromUnitRange(skybakeFractionOfRange(dist, top_radius_m - r, rho_m + H_m), size_mu);
  }
  if (ray_intersects_ground) {
    return 0.5 - 0.5 * skybakeTextureCoordFromUnitRange(skybakeFractionOfRange(dist_m, r - bottom_radius_m, rho_m),
                                                        size_mu / 2);
  }
  return 0.5 + 0.5 * skybakeTextureCoordFromUnitRange(skybakeFractionOfRange(dist_m, top_radius_m - r, rho_m + H_m),
                                                      size_mu / 2);
}

// The same for the ray (r, mu).
SKYBAKE_KERNEL Real skybakeScatteringCoordMu(Real r, Real mu, Real bottom_radius_m, Real top_radius_m, Real rho_m,
                                             Real H_m, int size_mu, bool ground_views, bool ray_intersects_ground) {
  return skybakeScatteringCoordMuAtDistance(
      r, skybakeDistanceToAtmosphereEnd(r, mu, bottom_radius_m, top_radius_m, ray_intersects_ground), bottom_radius_m,
      top_radius_m, rho_m, H_m, size_mu, ground_views, ray_intersects_ground);
}

// The multiple-scattering density table's mu coordinate: linear over
// [-1, 1] (density depends on the direction only, not on where the ray
// ends, and is smooth through the horizon).
SKYBAKE_KERNEL Real skybakeDensityCoordMu(Real mu, int size_mu) {
  return skybakeTextureCoordFromUnitRange((mu + 1.0) * 0.5, size_mu);
}

// The 4D tables' nu coordinate: linear, texel i at i / (size - 1).
SKYBAKE_KERNEL Real skybakeScatteringCoordNu(Real nu) { return (nu + 1.0) * 0.5; }

// ---- the irradiance table (2D: u = mu_s, v = r) ----

// The rows' altitudes (IrradianceRows): cosine_rows 1, the altitude share
// (r - bottom) / (top - bottom) at row i of n is (1 - cos(pi i / (n - 1))) /
// 2, rows dense near the ground (the aerosol layer) and near the top (where
// the sky above thins to nothing); cosine_rows 0, linear (format versions 2
// to 8).
SKYBAKE_KERNEL Real skybakeIrradianceRowUnit(Real altitude_share, int cosine_rows) {
  if (cosine_rows == 0) return altitude_share;
  return acos(clamp(1.0 - 2.0 * altitude_share, -1.0, 1.0)) / SKYBAKE_PI;
}

// The sun cosine whose place on the sun axis a row at radius r reads
// (horizon_relative 1, with the cosine rows): the axis's horizon texel moved
// to the sun on r's own horizon (mu_h = skybakeTangentZenithCosine, below
// the ground's), the ends (mu_s_min and the zenith) kept, linear in between
// on either side; so that each row's own sunset, where its sky's light falls
// steepest, sits on the same texel. mu_s_min >= mu_h (a sun range that ends
// before r's own sunset): the cosine itself.
SKYBAKE_KERNEL Real skybakeIrradianceSunCosine(Real mu_s, Real r, Real bottom_radius_m, Real mu_s_min,
                                               int horizon_relative) {
  if (horizon_relative == 0) return mu_s;
  Real mu_h = skybakeTangentZenithCosine(max(r, bottom_radius_m), bottom_radius_m);
  if (!(mu_s_min < mu_h)) return mu_s;
  if (mu_s >= mu_h) return (mu_s - mu_h) / (1.0 - mu_h);
  return mu_s_min * (mu_s - mu_h) / (mu_s_min - mu_h);
}

// The r coordinate.
SKYBAKE_KERNEL Real skybakeIrradianceCoordR(Real r, Real bottom_radius_m, Real top_radius_m, int size_r,
                                            int cosine_rows) {
  return skybakeTextureCoordFromUnitRange(
      skybakeIrradianceRowUnit((r - bottom_radius_m) / (top_radius_m - bottom_radius_m), cosine_rows), size_r);
}

// The radius of row i_r of size_r.
SKYBAKE_KERNEL Real skybakeIrradianceRowRadius(int i_r, int size_r, Real bottom_radius_m, Real top_radius_m,
                                               int cosine_rows) {
  Real x = Real(i_r) / Real(size_r - 1);
  Real share = cosine_rows == 0 ? x : 0.5 * (1.0 - cos(SKYBAKE_PI * x));
  return bottom_radius_m + share * (top_radius_m - bottom_radius_m);
}
