// Inverse maps: texel index -> the configuration at the texel's centre. The
// bake evaluates each table there, so forward(inverse(texel)) == texel is the
// round-trip property the tests check.
#include "data_formats/parameterization/texture_mapping.h"

#include <algorithm>
#include <cmath>

namespace skybake {
namespace {

double texelCentre(int index, int size) { return (index + 0.5) / size; }

// Cosine of a ray from r whose distance to the top boundary is dist; the ray
// with dist = 0 is one starting on the top boundary going straight up.
double muFromDistanceToTop(double r, double dist, double rho, double H) {
  return dist == 0.0 ? 1.0 : clampCosine((H * H - rho * rho - dist * dist) / (2.0 * r * dist));
}

}  // namespace

double muSFromUnitCoord(const AtmosphereDomain& d, double x) {
  const MuSDistanceRange range = MuSDistanceRange::of(d);
  const MuSUnitCoordMap map = MuSUnitCoordMap::of(d);
  if (map.below_share > 0.0) {
    if (x < map.below_share) {
      return clampCosine(d.mu_s_min * SunBelowHorizonAxis::sineFromDepth(1.0 - x / map.below_share));
    }
    // Bruneton's coordinate over the day.
    x = map.day_coord_at_horizon + (x - map.below_share) / (1.0 - map.below_share) * (1.0 - map.day_coord_at_horizon);
  }
  const double A = range.fraction(d, d.mu_s_min);
  const double a = (A - x * A) / (1.0 + x * A);
  const double dist = range.d_min + std::min(a, A) * (range.d_max - range.d_min);
  const double H = range.d_max;
  return dist == 0.0 ? 1.0 : clampCosine((H * H - dist * dist) / (2.0 * d.bottom_radius_m * dist));
}

RMu transmittanceTexelConfig(const AtmosphereDomain& d, int size_mu, int size_r, int i_mu, int i_r) {
  const double x_mu = unitRangeFromTextureCoord(texelCentre(i_mu, size_mu), size_mu);
  const double x_r = unitRangeFromTextureCoord(texelCentre(i_r, size_r), size_r);
  const double H = d.horizonToTopDistance();
  const double rho = H * x_r;
  const double r = std::sqrt(rho * rho + d.bottom_radius_m * d.bottom_radius_m);
  const double d_min = d.top_radius_m - r;
  const double d_max = rho + H;
  const double dist = d_min + x_mu * (d_max - d_min);
  return {r, muFromDistanceToTop(r, dist, rho, H)};
}

RMuS irradianceTexelConfig(const AtmosphereDomain& d, int size_mu_s, int size_r, int i_mu_s, int i_r) {
  const int cosine_rows = d.irradianceCosineRows();
  const double r = kernel::skybakeIrradianceRowRadius(i_r, size_r, d.bottom_radius_m, d.top_radius_m, cosine_rows);
  // The axis's cosine, turned back into the sun's at this row
  // (skybakeIrradianceSunCosine inverted).
  const double axis_mu_s = muSFromIrradianceTexel(d, size_mu_s, i_mu_s);
  const double mu_h = kernel::skybakeTangentZenithCosine(r, d.bottom_radius_m);
  if (cosine_rows == 0 || !(d.mu_s_min < mu_h)) return {r, axis_mu_s};
  const double mu_s =
      axis_mu_s >= 0.0 ? mu_h + axis_mu_s * (1.0 - mu_h) : mu_h + axis_mu_s * (d.mu_s_min - mu_h) / d.mu_s_min;
  return {r, clampCosine(mu_s)};
}

int irradianceDepthChannel(const AtmosphereParameters& a) {
  int best = 0;
  double best_share = 2.0;  // above any share
  for (int c = 0; c < a.laneCount(); ++c) {
    const double absorption = a.absorption_extinction[c];
    const double extinction = a.rayleigh_scattering[c] + a.mie_extinction[c] + absorption;
    if (!(extinction > 0.0)) continue;
    const double share = absorption / extinction;
    if (share < best_share) {
      best_share = share;
      best = c;
    }
  }
  return best;
}

double rFromScatteringTexel(const AtmosphereDomain& d, const ScatteringSizes& s, int i_r) {
  const double x = unitRangeFromTextureCoord(texelCentre(i_r, s.r), s.r);
  return d.radiusAtDistanceToHorizon(d.scattering_rho_min_m + x * (d.scattering_rho_max_m - d.scattering_rho_min_m));
}

double muSFromScatteringTexel(const AtmosphereDomain& d, const ScatteringSizes& s, int i_mu_s) {
  const double x = unitRangeFromTextureCoord(texelCentre(i_mu_s, s.mu_s), s.mu_s);
  return muSFromUnitCoord(
      d, d.scattering_mu_s_coord_min + x * (d.scattering_mu_s_coord_max - d.scattering_mu_s_coord_min));
}

double muSFromIrradianceTexel(const AtmosphereDomain& d, int size, int i_mu_s) {
  return muSFromUnitCoord(d, unitRangeFromTextureCoord(texelCentre(i_mu_s, size), size));
}

ScatteringTexelConfig scatteringTexelConfig(const AtmosphereDomain& d, const ScatteringSizes& s, int i_r, int i_mu,
                                            int i_mu_s, int i_nu) {
  const double H = d.horizonToTopDistance();
  const double r = rFromScatteringTexel(d, s, i_r);
  const double rho = d.distanceToHorizon(r);
  const double u_mu = texelCentre(i_mu, s.mu);
  double mu;
  bool ground;
  if (!d.scattering_ground_views) {
    const double d_min = d.top_radius_m - r;
    const double dist = d_min + (rho + H - d_min) * unitRangeFromTextureCoord(u_mu, s.mu);
    mu = muFromDistanceToTop(r, dist, rho, H);
    ground = false;
  } else if (u_mu < 0.5) {
    const double d_min = r - d.bottom_radius_m;
    const double d_max = rho;
    const double dist = d_min + (d_max - d_min) * unitRangeFromTextureCoord(1.0 - 2.0 * u_mu, s.mu / 2);
    mu = dist == 0.0 ? -1.0 : clampCosine(-(rho * rho + dist * dist) / (2.0 * r * dist));
    ground = true;
  } else {
    const double d_min = d.top_radius_m - r;
    const double d_max = rho + H;
    const double dist = d_min + (d_max - d_min) * unitRangeFromTextureCoord(2.0 * u_mu - 1.0, s.mu / 2);
    mu = muFromDistanceToTop(r, dist, rho, H);
    ground = false;
  }
  const double mu_s = muSFromScatteringTexel(d, s, i_mu_s);
  // nu texels sit at -1 + 2 i / (nu_size - 1): both ends are tabulated.
  return {r, mu, mu_s, clampNu(nuOfScatteringSlice(i_nu, s.nu), mu, mu_s), ground};
}

}  // namespace skybake
