#include "baker/reference/lit_air_guide.h"
#include "data_formats/angles.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "baker/numerics/optical_depth_integral.h"
#include "data_formats/parameterization/ray_sphere.h"
#include "runtime/physics/atmosphere_ray.h"
#include "runtime/physics/phase_functions.h"

namespace skybake {
namespace {

// Altitudes of the grid: (i / (n - 1))^2 of the atmosphere's height, dense
// near the ground where the light arriving changes fastest with altitude.
constexpr int kAltitudeNodes = 16;
// Sun zenith angles of the grid, at a point: from 80 deg (a low sun, the
// first sun a query toward sunlit air can have at a vertex above its camera)
// to 140 deg (beyond it no sunlit air is in view of the atmosphere on Earth,
// and the cell of 140 deg serves every point further round) in 1 deg steps:
// the band of sunlit air moves by about half a degree of elevation per
// degree of sun, so neighbouring cells overlap.
constexpr double kFirstSunZenith_deg = 80.0;
constexpr double kSunZenithStep_deg = 1.0;
constexpr int kSunZenithNodes = 61;
// Directions per cell: elevation bins uniform in asinh((elevation -
// horizon) / kHorizonScale_rad), a fifth of a degree wide at the point's
// horizon, where the sunlit air is seen in deep twilight, and widening to
// some 10 deg toward the zenith and nadir; azimuth bins from the sun's to
// the opposite azimuth (the other side by symmetry).
constexpr int kElevationBins = 48;
constexpr int kAzimuthBins = 24;
constexpr double kHorizonScale_rad = kPi / 180.0;
// Midpoint steps along each direction's ray: a proposal needs the shape of
// the light's distribution, not its last percent.
constexpr int kRaySteps = 64;
// The sun's optical depth table: rows (i / (n - 1))^2 of the height,
// columns ((mu_s - horizon) / (1 - horizon))^(1/2), dense at the horizon.
constexpr int kSunDepthRows = 64;
constexpr int kSunDepthColumns = 64;
// Below this length of the sun's horizontal part at a point, the sun is
// (nearly) straight above or below and any horizontal axis serves.
constexpr double kSmallestSunwardLength = 1e-9;

double azimuthBinWidth() { return kPi / kAzimuthBins; }

}  // namespace

struct LitAirGuide::Cell {
  // Filled in two steps: the light scattered once (which needs nothing but
  // the sun), then the light scattered twice (which needs the once-scattered
  // light of the cells along each direction) and the distributions.
  std::once_flag once_scattered_done, twice_scattered_done;
  double horizon_elevation = 0.0;  // rad, below 0 above the ground
  double w_low = 0.0, w_step = 0.0;
  glm::dvec3 point, sun;              // the cell's point and sun (sun in the x-z plane)
  std::vector<SpectrumD> once_flux;   // [elevation][azimuth]: radiance x solid angle, until the second step
  SpectrumD once_mean_radiance{0.0};  // over all directions
  std::vector<double> probability;    // [elevation][azimuth], summing to 1; empty: nothing to propose
  std::vector<double> elevation_cdf;  // kElevationBins + 1
  std::vector<double> azimuth_cdf;    // kElevationBins x (kAzimuthBins + 1)
  SpectrumD mean_radiance{0.0};       // once and twice scattered, over all directions

  double elevationAt(double w) const { return horizon_elevation + kHorizonScale_rad * std::sinh(w); }
  double binLowSine(int i) const {
    return std::sin(std::clamp(elevationAt(w_low + i * w_step), -0.5 * kPi, 0.5 * kPi));
  }
  // Solid angle of elevation bin i over one azimuth bin on both sides.
  double binSolidAngle(int i) const { return 2.0 * azimuthBinWidth() * (binLowSine(i + 1) - binLowSine(i)); }
  int elevationBin(double elevation) const {
    const double w = std::asinh((elevation - horizon_elevation) / kHorizonScale_rad);
    return std::clamp(static_cast<int>(std::floor((w - w_low) / w_step)), 0, kElevationBins - 1);
  }
  // The direction at the centre of bin (i, j), on the positive side.
  glm::dvec3 binCentre(int i, int j) const {
    const double elevation = elevationAt(w_low + (i + 0.5) * w_step);
    const double azimuth = (j + 0.5) * azimuthBinWidth();
    return directionFromElevationAzimuth(elevation, azimuth);
  }
};

LitAirGuide::LitAirGuide(const AtmosphereParameters& atmosphere)
    : a_(atmosphere), media_(a_), cells_(new Cell[kAltitudeNodes * kSunZenithNodes]) {}

LitAirGuide::~LitAirGuide() = default;

double LitAirGuide::sunDepthCoordinate(double r, double mu_s, double& mu_horizon) const {
  mu_horizon = -safeSqrt(1.0 - std::pow(a_.bottom_radius_m / std::max(r, a_.bottom_radius_m), 2));
  return std::sqrt(std::clamp((mu_s - mu_horizon) / (1.0 - mu_horizon), 0.0, 1.0));
}

SpectrumD LitAirGuide::sunTransmittance(const glm::dvec3& point, const glm::dvec3& sun) const {
  static_assert(kSunDepthRows > 1 && kSunDepthColumns > 1);
  const double height = a_.top_radius_m - a_.bottom_radius_m;
  const double r = std::clamp(glm::length(point), a_.bottom_radius_m, a_.top_radius_m);
  const double mu_s = clampCosine(glm::dot(point, sun) / glm::length(point));
  std::call_once(sun_depth_once_, [&] {
    sun_depth_.resize(kSunDepthRows * kSunDepthColumns);
    for (int row = 0; row < kSunDepthRows; ++row) {
      const double row_r = a_.bottom_radius_m + height * std::pow(double(row) / (kSunDepthRows - 1), 2);
      double mu_h = 0.0;
      sunDepthCoordinate(row_r, 1.0, mu_h);
      for (int column = 0; column < kSunDepthColumns; ++column) {
        const double v = double(column) / (kSunDepthColumns - 1);
        sun_depth_[row * kSunDepthColumns + column] =
            integrateOpticalDepthToTop(media_, row_r, clampCosine(mu_h + (1.0 - mu_h) * v * v));
      }
    }
  });
  double mu_h = 0.0;
  const double column_coordinate = sunDepthCoordinate(r, mu_s, mu_h) * (kSunDepthColumns - 1);
  if (mu_s < mu_h) return SpectrumD(0.0);
  const double row_coordinate = std::sqrt((r - a_.bottom_radius_m) / height) * (kSunDepthRows - 1);
  const int row = std::min(static_cast<int>(row_coordinate), kSunDepthRows - 2);
  const int column = std::min(static_cast<int>(column_coordinate), kSunDepthColumns - 2);
  const double fr = row_coordinate - row, fc = column_coordinate - column;
  auto at = [&](int i, int j) { return sun_depth_[i * kSunDepthColumns + j]; };
  const SpectrumD depth = (at(row, column) * (1.0 - fc) + at(row, column + 1) * fc) * (1.0 - fr) +
                          (at(row + 1, column) * (1.0 - fc) + at(row + 1, column + 1) * fc) * fr;
  return glm::exp(-depth);
}

// Radiance W m^-2 sr^-1 nm^-1 arriving at `point` along -dir from
// scattering along the ray in `dir`, per unit of `source(y)` at each point
// y: the midpoint rule over kRaySteps steps.
template <typename SourceFn>
SpectrumD LitAirGuide::alongRay(const glm::dvec3& point, const glm::dvec3& dir, SourceFn&& source) const {
  const AtmosphereRay ray = atmosphereRay(a_.bottom_radius_m, a_.top_radius_m, point, dir, 0.0);
  if (!ray.inside || !(ray.length > 0.0)) return SpectrumD(0.0);
  const double step = ray.length / kRaySteps;
  SpectrumD depth(0.0), radiance(0.0);
  for (int s = 0; s < kRaySteps; ++s) {
    const glm::dvec3 y = point + dir * ((s + 0.5) * step);
    const double h = glm::length(y) - a_.bottom_radius_m;
    const SpectrumD extinction = media_.extinction(h) * step;
    radiance += source(y, h) * glm::exp(-(depth + 0.5 * extinction)) * step;
    depth += extinction;
  }
  return radiance;
}

void LitAirGuide::computeOnceScattered(Cell& cell, int altitude_index, int sun_index) const {
  const double height = a_.top_radius_m - a_.bottom_radius_m;
  const double r = a_.bottom_radius_m + height * std::pow(double(altitude_index) / (kAltitudeNodes - 1), 2);
  const double sun_zenith = (kFirstSunZenith_deg + sun_index * kSunZenithStep_deg) * kPi / 180.0;
  cell.point = glm::dvec3(0.0, 0.0, r);
  cell.sun = directionFromZenithAzimuth(sun_zenith, 0.0);
  cell.horizon_elevation = -std::acos(std::min(a_.bottom_radius_m / r, 1.0));
  cell.w_low = std::asinh((-0.5 * kPi - cell.horizon_elevation) / kHorizonScale_rad);
  cell.w_step = (std::asinh((0.5 * kPi - cell.horizon_elevation) / kHorizonScale_rad) - cell.w_low) / kElevationBins;

  const SpectrumD rayleigh(a_.rayleigh_scattering), mie(a_.mie_scattering), sun_irradiance(a_.sun_irradiance);
  cell.once_flux.assign(kElevationBins * kAzimuthBins, SpectrumD(0.0));
  SpectrumD total(0.0);
  for (int i = 0; i < kElevationBins; ++i) {
    for (int j = 0; j < kAzimuthBins; ++j) {
      const glm::dvec3 dir = cell.binCentre(i, j);
      const double nu = glm::dot(dir, cell.sun);
      const double rayleigh_phase = rayleighPhase(nu), mie_phase = cornetteShanksPhase(a_.mie_phase_g, nu);
      const SpectrumD radiance = alongRay(cell.point, dir, [&](const glm::dvec3& y, double h) {
        const SpectrumD light = sunTransmittance(y, cell.sun);
        if (light == SpectrumD(0.0)) return SpectrumD(0.0);
        return (rayleigh * (media_.rayleighDensity(h) * rayleigh_phase) + mie * (media_.mieDensity(h) * mie_phase)) *
               light * sun_irradiance;
      });
      cell.once_flux[i * kAzimuthBins + j] = radiance * cell.binSolidAngle(i);
      total += cell.once_flux[i * kAzimuthBins + j];
    }
  }
  cell.once_mean_radiance = total / (4.0 * kPi);
}

void LitAirGuide::computeTwiceScattered(Cell& cell) const {
  // The light scattered a second time toward the point, the first time's
  // light taken as isotropic at each scattering point (its mean over
  // directions): in deep twilight the blue light near the ground has mostly
  // come down from the shadowed air above, lit by the sunlit air that the
  // ground cannot see, so the directions must also aim there.
  const SpectrumD rayleigh(a_.rayleigh_scattering), mie(a_.mie_scattering);
  std::vector<SpectrumD> flux(cell.once_flux);
  SpectrumD total(0.0);
  for (int i = 0; i < kElevationBins; ++i) {
    for (int j = 0; j < kAzimuthBins; ++j) {
      const SpectrumD radiance = alongRay(cell.point, cell.binCentre(i, j), [&](const glm::dvec3& y, double h) {
        return (rayleigh * media_.rayleighDensity(h) + mie * media_.mieDensity(h)) *
               onceScatteredMeanRadiance(y, cell.sun);
      });
      flux[i * kAzimuthBins + j] += radiance * cell.binSolidAngle(i);
      total += flux[i * kAzimuthBins + j];
    }
  }
  cell.once_flux = {};
  cell.mean_radiance = total / (4.0 * kPi);
  // Each channel's distribution normalized, then averaged: a channel whose
  // light comes from elsewhere (blue from higher, less attenuated air) gets
  // its share of the directions however much dimmer it is.
  int channels = 0;
  for (int k = 0; k < 4; ++k) channels += total[k] > 0.0 && std::isfinite(total[k]);
  if (channels == 0) return;
  cell.probability.assign(flux.size(), 0.0);
  for (size_t b = 0; b < flux.size(); ++b) {
    for (int k = 0; k < 4; ++k) {
      if (total[k] > 0.0 && std::isfinite(total[k])) cell.probability[b] += flux[b][k] / total[k] / channels;
    }
  }
  cell.elevation_cdf.assign(kElevationBins + 1, 0.0);
  cell.azimuth_cdf.assign(kElevationBins * (kAzimuthBins + 1), 0.0);
  for (int i = 0; i < kElevationBins; ++i) {
    double row = 0.0;
    double* cdf = &cell.azimuth_cdf[i * (kAzimuthBins + 1)];
    for (int j = 0; j < kAzimuthBins; ++j) {
      row += cell.probability[i * kAzimuthBins + j];
      cdf[j + 1] = row;
    }
    cell.elevation_cdf[i + 1] = cell.elevation_cdf[i] + row;
  }
}

LitAirGuide::Cell& LitAirGuide::onceScatteredCell(int altitude_index, int sun_index) const {
  Cell& cell = cells_[altitude_index * kSunZenithNodes + sun_index];
  std::call_once(cell.once_scattered_done, [&] { computeOnceScattered(cell, altitude_index, sun_index); });
  return cell;
}

const LitAirGuide::Cell& LitAirGuide::cellAt(int altitude_index, int sun_index) const {
  Cell& cell = onceScatteredCell(altitude_index, sun_index);
  std::call_once(cell.twice_scattered_done, [&] { computeTwiceScattered(cell); });
  return cell;
}

LitAirGuide::GridPosition LitAirGuide::gridPosition(const glm::dvec3& point, const glm::dvec3& sun) const {
  GridPosition g;
  const double r = glm::length(point);
  const double height = a_.top_radius_m - a_.bottom_radius_m;
  const double a = std::sqrt(std::clamp((r - a_.bottom_radius_m) / height, 0.0, 1.0)) * (kAltitudeNodes - 1);
  g.altitude_index = std::min(static_cast<int>(a), kAltitudeNodes - 2);
  g.sun_up = clampCosine(glm::dot(sun, point) / r);
  const double s = std::clamp((std::acos(g.sun_up) * 180.0 / kPi - kFirstSunZenith_deg) / kSunZenithStep_deg, 0.0,
                              double(kSunZenithNodes - 1));
  g.sun_index = std::min(static_cast<int>(s), kSunZenithNodes - 2);
  const double fa = a - g.altitude_index, fs = s - g.sun_index;
  g.weight = {(1.0 - fa) * (1.0 - fs), fa * (1.0 - fs), (1.0 - fa) * fs, fa * fs};
  return g;
}

SpectrumD LitAirGuide::onceScatteredMeanRadiance(const glm::dvec3& point, const glm::dvec3& sun) const {
  const GridPosition g = gridPosition(point, sun);
  SpectrumD mean(0.0);
  for (int c = 0; c < 4; ++c) {
    if (g.weight[c] > 0.0)
      mean += onceScatteredCell(g.altitude_index + c % 2, g.sun_index + c / 2).once_mean_radiance * g.weight[c];
  }
  return mean;
}

LitAirGuide::Site LitAirGuide::siteAt(const glm::dvec3& point, const glm::dvec3& sun) const {
  Site site;
  const GridPosition g = gridPosition(point, sun);
  for (int c = 0; c < 4; ++c) site.cell[c] = &cellAt(g.altitude_index + c % 2, g.sun_index + c / 2);
  site.weight = g.weight;
  site.up = point / glm::length(point);
  const double sun_up = g.sun_up;
  double proposing = 0.0;
  for (int c = 0; c < 4; ++c) {
    if (!site.cell[c]->probability.empty()) proposing += site.weight[c];
  }
  for (int c = 0; c < 4; ++c) {
    site.sample_weight[c] = proposing > 0.0 && !site.cell[c]->probability.empty() ? site.weight[c] / proposing : 0.0;
  }
  glm::dvec3 sunward = sun - sun_up * site.up;
  const double sunward_length = glm::length(sunward);
  if (sunward_length > kSmallestSunwardLength) {
    sunward /= sunward_length;
  } else {
    const glm::dvec3 helper = std::abs(site.up.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    sunward = glm::normalize(glm::cross(helper, site.up));
  }
  site.sunward = sunward;
  site.side = glm::cross(site.up, sunward);
  return site;
}

SpectrumD LitAirGuide::meanInscatteredRadiance(const Site& site) const {
  SpectrumD mean(0.0);
  for (int c = 0; c < 4; ++c) mean += site.cell[c]->mean_radiance * site.weight[c];
  return mean;
}

glm::dvec3 LitAirGuide::sampleDirection(const Site& site, double u_elevation, double u_azimuth) const {
  // The cell, by the lowest part of u_elevation; the rest, rescaled, picks
  // the elevation bin and the sine within it.
  int last = 3;
  while (last > 0 && site.sample_weight[last] <= 0.0) --last;
  int c = 0;
  double u = u_elevation;
  while (c < last && (site.sample_weight[c] <= 0.0 || u >= site.sample_weight[c])) {
    u -= site.sample_weight[c];
    ++c;
  }
  const Cell& cell = *site.cell[c];
  const auto& e_cdf = cell.elevation_cdf;
  u = std::clamp(u / site.sample_weight[c], 0.0, std::nextafter(1.0, 0.0)) * e_cdf.back();
  const int i = std::clamp(static_cast<int>(std::upper_bound(e_cdf.begin(), e_cdf.end(), u) - e_cdf.begin()) - 1, 0,
                           kElevationBins - 1);
  const double e_fraction = std::clamp((u - e_cdf[i]) / std::max(e_cdf[i + 1] - e_cdf[i], 1e-300), 0.0, 1.0);
  const double sin_low = cell.binLowSine(i), sin_high = cell.binLowSine(i + 1);
  const double sin_e = sin_low + e_fraction * (sin_high - sin_low);
  // The side from the half u_azimuth falls in, the bin and the place in it
  // from the rest.
  const double side_sign = u_azimuth < 0.5 ? -1.0 : 1.0;
  const double* a_cdf = &cell.azimuth_cdf[i * (kAzimuthBins + 1)];
  const double target = std::min(std::abs(2.0 * u_azimuth - 1.0), std::nextafter(1.0, 0.0)) * a_cdf[kAzimuthBins];
  const int j = std::clamp(static_cast<int>(std::upper_bound(a_cdf, a_cdf + kAzimuthBins + 1, target) - a_cdf) - 1, 0,
                           kAzimuthBins - 1);
  const double a_fraction = std::clamp((target - a_cdf[j]) / std::max(a_cdf[j + 1] - a_cdf[j], 1e-300), 0.0, 1.0);
  const double azimuth = side_sign * (j + a_fraction) * azimuthBinWidth();
  const double cos_e = safeSqrt(1.0 - sin_e * sin_e);
  return glm::normalize(cos_e * (std::cos(azimuth) * site.sunward + std::sin(azimuth) * site.side) + sin_e * site.up);
}

double LitAirGuide::directionPdf(const Site& site, const glm::dvec3& dir) const {
  const double elevation = std::asin(clampCosine(glm::dot(dir, site.up)));
  const double azimuth = std::abs(std::atan2(glm::dot(dir, site.side), glm::dot(dir, site.sunward)));
  const int j = std::clamp(static_cast<int>(azimuth / azimuthBinWidth()), 0, kAzimuthBins - 1);
  double pdf = 0.0;
  for (int c = 0; c < 4; ++c) {
    if (site.sample_weight[c] <= 0.0) continue;
    const Cell& cell = *site.cell[c];
    const int i = cell.elevationBin(elevation);
    const double solid_angle = cell.binSolidAngle(i);
    if (solid_angle > 0.0) pdf += site.sample_weight[c] * cell.probability[i * kAzimuthBins + j] / solid_angle;
  }
  return pdf;
}

}  // namespace skybake
