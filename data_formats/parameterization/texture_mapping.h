// The parameterization contract between baker and runtime: where in each table
// a geometric configuration (r, mu, mu_s, nu) lives. Follows Bruneton (2017):
//  - r maps rho = sqrt(r^2 - bottom^2) over H = sqrt(top^2 - bottom^2), which
//    puts texels close together near the ground where the sky changes fastest;
//  - mu maps the distance to the boundary the ray ends on between its minimum
//    and maximum for that r; in 4D, rays that hit the ground take the lower
//    half of the mu axis and the others the upper half, so no lookup ever
//    interpolates across the horizon;
//  - mu_s: for a sun range that reaches below the horizon, half the axis
//    holds the suns below it, spaced by the sine of their depression down to
//    mu_s_min, and the other half the day, by Bruneton's distance-based
//    coordinate (SunAxisMapping; files before format version 5 use that
//    coordinate alone);
//  - nu is linear in [-1, 1].
// Texel centres land exactly on the domain ends (textureCoordFromUnitRange).
// Lookups: the forward maps (inline, hot in the runtime). Bakes: the inverse
// maps from a texel index to the configuration at its centre.
#pragma once

#include <algorithm>
#include <cmath>

#include "data_formats/config/atmosphere_parameters.h"
#include "data_formats/parameterization/ray_sphere.h"

namespace skybake {
namespace kernel {
#include "data_formats/kernel/texture_coordinates.glsl"
}  // namespace kernel

// How the sun axis of the 4D and irradiance tables spreads its texels.
enum class SunAxisMapping {
  // Bruneton's alone: (1 - a/A) / (1 + a) of the distance to the top toward
  // the sun. Dense near the horizon, sparse deep below it (for the built-in
  // Earth's 36 texels down to 108 deg: 108, 105, 102.7, 100.8 deg), where the
  // sky falls tenfold from one texel to the next. Bake files before format
  // version 5.
  DistanceToTop,
  // For a sun range reaching below the horizon: the first
  // kSunAxisBelowHorizonShare of the axis below it, by the sine of the sun's
  // depression (SunBelowHorizonAxis), the rest the day by Bruneton's
  // coordinate over the day alone. Format version 5 on.
  SplitAtHorizon,
};

// The share of the sun axis below the horizon (SplitAtHorizon): 18 of the
// 40 intervals between the default 41 texels, so that the default axis has
// a texel on the horizon, where the lookups' blend across mu_s changes
// (radianceBlend). For the built-in Earth's 18 deg below the horizon that
// takes the deepest spacing from 3 deg (DistanceToTop, 36 texels) to
// 1.25 deg, while the day's 22 intervals keep it as finely sampled as
// before (docs/MEASUREMENTS.md, "Resolution in deep twilight").
inline constexpr double kSunAxisBelowHorizonShare = 18.0 / 40.0;
// The spacing of the below-horizon texels at the horizon relative to their
// mean; it grows linearly to 2 minus this at the lowest sun. Civil twilight,
// where the sky's colour turns fastest, gets 0.75 deg texels on the default
// axis, the deep end 1.25 deg.
inline constexpr double kSunAxisHorizonSpacing = 0.75;

// Where the sky irradiance table's rows sit and how a lookup blends them.
enum class IrradianceRows {
  // Linear in altitude, blended geometrically (format versions 2 to 8).
  Linear,
  // Cosine spaced (skybakeIrradianceRowUnit), dense near the ground and the
  // top; the irradiance over the vertical optical depth above blended
  // geometrically (TableSampler::irradiance); each row's sun axis relative
  // to its own horizon (skybakeIrradianceSunCosine). Format version 9 on.
  CosineOverDepth,
};

// The channel whose vertical optical depth the irradiance rows are blended
// over (IrradianceRows::CosineOverDepth): the one whose extinction owes
// least to absorption (ties: the first), as the sky's light follows the air
// that scatters it; an absorbing layer (ozone) bends the optical depth of
// its own channels away from it.
int irradianceDepthChannel(const AtmosphereParameters& a);

// The part of the atmosphere's geometry that the parameterization needs, and
// the part of it the 4D tables cover.
struct AtmosphereDomain {
  double bottom_radius_m = 0.0;
  double top_radius_m = 0.0;
  // The lowest sun of the irradiance table and of the full mu_s coordinate.
  double mu_s_min = -1.0;
  // The 4D tables' ends in their axes' own coordinates: rho (the distance to
  // the horizon, see distanceToHorizon) at the r axis's ends, and the unit
  // sun coordinate (muSUnitCoord: 0 at mu_s_min, 1 at the zenith) at the
  // mu_s axis's ends. The whole domain is [0, H] and [0, 1]; a [scene]
  // narrows them, and the axes keep their texel spacing's shape over the
  // narrower range. A bake decides them (sceneDomain, baker/bake/bake_policy.h)
  // and its file states them.
  double scattering_rho_min_m = 0.0;
  double scattering_rho_max_m = 0.0;
  double scattering_mu_s_coord_min = 0.0;
  double scattering_mu_s_coord_max = 1.0;
  // Whether the 4D tables' mu axis holds rays that end on the ground (its
  // first half) as well as the sky (second half), or only the sky (all of
  // it): [scene] views_below_horizon.
  bool scattering_ground_views = true;
  // The sun axis's texel spacing (a bake file states it by its format version).
  SunAxisMapping sun_axis = SunAxisMapping::SplitAtHorizon;
  // The sky irradiance table's rows (a bake file states them by its format
  // version) and the channel they are blended over (irradianceDepthChannel).
  IrradianceRows irradiance_rows = IrradianceRows::CosineOverDepth;
  int irradiance_depth_channel = 0;
  // irradiance_rows as the kernel's cosine_rows flag (1 CosineOverDepth, 0 Linear).
  int irradianceCosineRows() const { return irradiance_rows == IrradianceRows::CosineOverDepth ? 1 : 0; }
  bool operator==(const AtmosphereDomain&) const = default;

  // The whole domain: every altitude, every sun up to sun.max_zenith_deg.
  static AtmosphereDomain fromParameters(const AtmosphereParameters& a) {
    AtmosphereDomain d{a.bottom_radius_m, a.top_radius_m, a.sunMuSMin()};
    d.scattering_rho_max_m = d.horizonToTopDistance();
    d.irradiance_depth_channel = irradianceDepthChannel(a);
    return d;
  }

  bool narrowed() const {
    return scattering_rho_min_m > 0.0 || scattering_rho_max_m < horizonToTopDistance() ||
           scattering_mu_s_coord_min > 0.0 || scattering_mu_s_coord_max < 1.0 || !scattering_ground_views;
  }
  // Distance from the ground to the top boundary along the horizontal: the
  // longest path a ray that does not hit the ground spends above one point.
  double horizonToTopDistance() const { return kernel::skybakeDistanceToHorizon(top_radius_m, bottom_radius_m); }
  // rho: the distance to the horizon from radius r.
  double distanceToHorizon(double r) const { return kernel::skybakeDistanceToHorizon(r, bottom_radius_m); }
  double radiusAtDistanceToHorizon(double rho) const {
    return std::sqrt(rho * rho + bottom_radius_m * bottom_radius_m);
  }
};

// The forward maps are the kernel data_formats/kernel/texture_coordinates.glsl
// in double, the one source the shaders share; below, their C++ names and
// the constants of a domain worked out once.
inline constexpr auto& textureCoordFromUnitRange = kernel::skybakeTextureCoordFromUnitRange;
inline double unitRangeFromTextureCoord(double u, int size) { return (u - 0.5 / size) / (1.0 - 1.0 / size); }
inline constexpr auto& fractionOfRange = kernel::skybakeFractionOfRange;

// ---- transmittance (2D: u = mu across, v = r down) ----

struct TextureCoord2D {
  double u;
  double v;
};

// The mu coordinate at one r, its constants worked out once: for loops over
// many directions from one point (selects only, so they vectorize).
struct TransmittanceMuCoordAtR {
  double r, top_radius_m;
  double dist_min, dist_max;  // straight up, and toward the horizon
  int size_mu;
  // rho = distanceToHorizon(r) and H = horizonToTopDistance().
  static TransmittanceMuCoordAtR of(const AtmosphereDomain& d, int size_mu, double r, double rho, double H) {
    return {r, d.top_radius_m, d.top_radius_m - r, rho + H, size_mu};
  }
  static TransmittanceMuCoordAtR of(const AtmosphereDomain& d, int size_mu, double r) {
    return of(d, size_mu, r, d.distanceToHorizon(r), d.horizonToTopDistance());
  }
  double operator()(double mu) const {
    return kernel::skybakeOpticalDepthCoordMu(r, mu, top_radius_m, dist_min, dist_max, size_mu);
  }
  // The same from the direction's distance to the top.
  double atDistance(double dist_to_top_m) const {
    return kernel::skybakeOpticalDepthCoordMuAtDistance(dist_to_top_m, dist_min, dist_max, size_mu);
  }
};

// The mu coordinate alone, for callers that hold rho = distanceToHorizon(r)
// and H = horizonToTopDistance() for many directions from one r.
inline double transmittanceCoordMu(const AtmosphereDomain& d, int size_mu, double r, double rho, double H, double mu) {
  return TransmittanceMuCoordAtR::of(d, size_mu, r, rho, H)(mu);
}

// The r coordinate alone, from rho = distanceToHorizon(r).
inline double transmittanceCoordR(const AtmosphereDomain& d, int size_r, double rho) {
  return kernel::skybakeOpticalDepthCoordR(rho, d.horizonToTopDistance(), size_r);
}

inline TextureCoord2D transmittanceCoordFromRMu(const AtmosphereDomain& d, int size_mu, int size_r, double r,
                                                double mu) {
  const double H = d.horizonToTopDistance();
  const double rho = d.distanceToHorizon(r);
  return {transmittanceCoordMu(d, size_mu, r, rho, H, mu), transmittanceCoordR(d, size_r, rho)};
}

// ---- scattering (4D) ----

struct ScatteringCoord {
  double u_nu;    // [0, 1], linear in nu; texel i sits at i / (nu_size - 1)
  double u_mu_s;  // texture coordinate
  double u_mu;    // texture coordinate; < 0.5 for rays that hit the ground
  double u_r;     // texture coordinate
};

struct ScatteringSizes {
  int r;
  int mu;
  int mu_s;
  int nu;
  static ScatteringSizes fromTextureSizes(const TextureSizes& s) {
    return {s.scattering_r, s.scattering_mu, s.scattering_mu_s, s.scattering_nu};
  }
};

// The distance from the ground to the top toward a sun, as a fraction of its
// range (a; d_min straight up, d_max = H along the horizon).
struct MuSDistanceRange {
  double d_min;
  double d_max;
  double fraction(const AtmosphereDomain& d, double mu_s) const {
    return (distanceToOuterSphere(d.bottom_radius_m, mu_s, d.top_radius_m) - d_min) / (d_max - d_min);
  }
  static MuSDistanceRange of(const AtmosphereDomain& d) {
    return {d.top_radius_m - d.bottom_radius_m, d.horizonToTopDistance()};
  }
};

// The unit coordinate of the suns below the horizon (SplitAtHorizon): with
// t = mu_s / mu_s_min (the sine of the depression over the lowest sun's; 0
// at the horizon, 1 at mu_s_min) and s in [0, 1] from the horizon down,
// t = c s + (1 - c) s^2 for c = kSunAxisHorizonSpacing. The lookups' s from
// t is the kernel's skybakeSunDepthFromSine; the bake's t from s is here.
struct SunBelowHorizonAxis {
  static double sineFromDepth(double s) {
    constexpr double c = kSunAxisHorizonSpacing;
    return c * s + (1.0 - c) * s * s;
  }
};

// The sun coordinate over the whole sun range: 1 at the zenith, 0 at
// mu_s_min. Bruneton's: a = 0 at the zenith, a = A at mu_s_min; (1 - a/A) /
// (1 + a) compresses the high sun and spreads the horizon, where the sky
// changes fastest. SplitAtHorizon puts that over the day alone (from its
// value day_coord_at_horizon at the horizon to 1) in the upper
// 1 - below_share of the axis, and the suns below the horizon in the lower
// below_share (SunBelowHorizonAxis). below_share is 0 for DistanceToTop and
// for a sun range that stays above the horizon.
// muSUnitCoord with the domain's constants worked out once.
struct MuSUnitCoordMap : kernel::SkybakeSunCoordMap {
  static MuSUnitCoordMap of(const AtmosphereDomain& d) {
    const MuSDistanceRange range = MuSDistanceRange::of(d);
    const double A = range.fraction(d, d.mu_s_min);
    const bool split = d.sun_axis == SunAxisMapping::SplitAtHorizon && d.mu_s_min < 0.0 && A > 1.0;
    MuSUnitCoordMap m;
    m.bottom_radius_m = d.bottom_radius_m;
    m.top_radius_m = d.top_radius_m;
    m.d_min = range.d_min;
    m.inverse_d_span = 1.0 / (range.d_max - range.d_min);
    m.inverse_A = A > 0.0 ? 1.0 / A : 0.0;
    m.defined = A > 0.0 ? 1.0 : 0.0;
    m.below_share = split ? kSunAxisBelowHorizonShare : 0.0;
    m.day_coord_at_horizon = split ? 0.5 * (1.0 - 1.0 / A) : 0.0;
    m.inverse_mu_s_min = split ? 1.0 / d.mu_s_min : 0.0;
    m.horizon_spacing = kSunAxisHorizonSpacing;
    return m;
  }
  double operator()(double mu_s) const { return kernel::skybakeSunUnitCoord(*this, mu_s); }
};
inline double muSUnitCoord(const AtmosphereDomain& d, double mu_s) { return MuSUnitCoordMap::of(d)(mu_s); }

// The sun at unit coordinate x (the inverse of muSUnitCoord).
double muSFromUnitCoord(const AtmosphereDomain& d, double x);

// The 4D tables' mu_s texture coordinate: the unit coordinate over the
// tables' sun range (outside it the lookup clamps to the range's ends).
// scatteringCoordMuS with the domain's constants worked out once (see
// MuSUnitCoordMap).
struct ScatteringMuSCoordMap {
  MuSUnitCoordMap unit;
  double coord_min, inverse_coord_span;  // 0 where the range is a point (see fractionOfRange)
  int size_mu_s;
  static ScatteringMuSCoordMap of(const AtmosphereDomain& d, int size_mu_s) {
    const double span = d.scattering_mu_s_coord_max - d.scattering_mu_s_coord_min;
    return {MuSUnitCoordMap::of(d), d.scattering_mu_s_coord_min, span > 0.0 ? 1.0 / span : 0.0, size_mu_s};
  }
  double operator()(double mu_s) const {
    return kernel::skybakeScatteringCoordMuS(unit(mu_s), coord_min, inverse_coord_span, size_mu_s);
  }
};
inline double scatteringCoordMuS(const AtmosphereDomain& d, int size_mu_s, double mu_s) {
  return ScatteringMuSCoordMap::of(d, size_mu_s)(mu_s);
}

// The 4D tables' r texture coordinate: rho over the tables' altitude range.
inline double scatteringCoordR(const AtmosphereDomain& d, int size_r, double rho) {
  return kernel::skybakeScatteringCoordR(rho, d.scattering_rho_min_m, d.scattering_rho_max_m, size_r);
}

// The mu coordinate alone (see transmittanceCoordMu).
inline double scatteringCoordMu(const AtmosphereDomain& d, int size_mu, double r, double rho, double H, double mu,
                                bool ray_intersects_ground) {
  return kernel::skybakeScatteringCoordMu(r, mu, d.bottom_radius_m, d.top_radius_m, rho, H, size_mu,
                                          d.scattering_ground_views, ray_intersects_ground);
}
// The same from the ray's distance to its end, for callers that hold it.
inline double scatteringCoordMuAtDistance(const AtmosphereDomain& d, int size_mu, double r, double rho, double H,
                                          double dist_m, bool ray_intersects_ground) {
  return kernel::skybakeScatteringCoordMuAtDistance(r, dist_m, d.bottom_radius_m, d.top_radius_m, rho, H, size_mu,
                                                    d.scattering_ground_views, ray_intersects_ground);
}

// ---- irradiance (2D: u = mu_s across, v = r down) ----

// mu_s uses the scattering table's coordinate (dense near the horizon, ending
// at mu_s_min): across the terminator irradiance falls tenfold within a few
// degrees, which a coordinate linear in mu_s would straddle with one texel.
inline TextureCoord2D irradianceCoordFromRMuS(const AtmosphereDomain& d, int size_mu_s, int size_r, double r,
                                              double mu_s) {
  const int cosine_rows = d.irradianceCosineRows();
  const double axis_mu_s =
      kernel::skybakeIrradianceSunCosine(mu_s, std::min(r, d.top_radius_m), d.bottom_radius_m, d.mu_s_min, cosine_rows);
  return {textureCoordFromUnitRange(muSUnitCoord(d, axis_mu_s), size_mu_s),
          kernel::skybakeIrradianceCoordR(r, d.bottom_radius_m, d.top_radius_m, size_r, cosine_rows)};
}

inline ScatteringCoord scatteringCoordFromRMuMuSNu(const AtmosphereDomain& d, const ScatteringSizes& s, double r,
                                                   double mu, double mu_s, double nu, bool ray_intersects_ground) {
  const double H = d.horizonToTopDistance();
  const double rho = d.distanceToHorizon(r);
  return {kernel::skybakeScatteringCoordNu(nu), scatteringCoordMuS(d, s.mu_s, mu_s),
          scatteringCoordMu(d, s.mu, r, rho, H, mu, ray_intersects_ground), scatteringCoordR(d, s.r, rho)};
}

// The multiple-scattering density table shares the scattering table's r,
// mu_s and nu axes but maps mu linearly over [-1, 1], without the horizon
// split: density depends on the direction only, not on where the ray ends,
// and is smooth through the horizon. (In the split layout the ground half is
// degenerate at r = bottom, where every ground ray points straight down.)
inline constexpr auto& densityCoordMu = kernel::skybakeDensityCoordMu;
inline double muFromDensityTexel(int i_mu, int size_mu) { return clampCosine(-1.0 + 2.0 * i_mu / (size_mu - 1)); }

// The configuration at the centre of a texel.
struct ScatteringTexelConfig {
  double r;
  double mu;
  double mu_s;
  double nu;
  bool ray_intersects_ground;
};

double rFromScatteringTexel(const AtmosphereDomain& d, const ScatteringSizes& s, int i_r);
double muSFromScatteringTexel(const AtmosphereDomain& d, const ScatteringSizes& s, int i_mu_s);
// mu_s at the centre of texel i_mu_s of the irradiance table's mu_s axis of
// `size` texels (the whole sun range; the 4D tables' axis may be narrower).
double muSFromIrradianceTexel(const AtmosphereDomain& d, int size, int i_mu_s);
ScatteringTexelConfig scatteringTexelConfig(const AtmosphereDomain& d, const ScatteringSizes& s, int i_r, int i_mu,
                                            int i_mu_s, int i_nu);

struct RMu {
  double r;
  double mu;
};
RMu transmittanceTexelConfig(const AtmosphereDomain& d, int size_mu, int size_r, int i_mu, int i_r);

struct RMuS {
  double r;
  double mu_s;
};
// (r, mu_s) at an irradiance texel centre.
RMuS irradianceTexelConfig(const AtmosphereDomain& d, int size_mu_s, int size_r, int i_mu_s, int i_r);

// The nu a slice of the 4D tables stands for: -1 + 2 i / (nu_size - 1).
inline double nuOfScatteringSlice(int i_nu, int nu_size) { return clampCosine(-1.0 + 2.0 * i_nu / (nu_size - 1)); }

// The range of nu a direction with zenith cosine mu can make with a sun at
// zenith cosine mu_s; texels outside it describe impossible geometry and are
// evaluated at the nearest possible nu.
inline double clampNu(double nu, double mu, double mu_s) {
  const double spread = safeSqrt((1.0 - mu * mu) * (1.0 - mu_s * mu_s));
  return std::clamp(nu, mu * mu_s - spread, mu * mu_s + spread);
}

}  // namespace skybake
