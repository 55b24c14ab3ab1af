// Sky: loading a bake, and the altitudes and sun angles its tables cover.
// The lookups live beside it, one file each: sky_radiance.cpp,
// sky_radiance_to_point.cpp, sky_twilight.cpp (single scattering integrated
// with the sun below the horizon), sky_irradiance.cpp, sky_transmittance.cpp,
// sky_batch.cpp.
#include "runtime/sky.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "runtime/colour/channel_luminance.h"

namespace skybake {
namespace {

// Lookups this close outside a baked range count as inside: the range's
// ends come back from the tables' coordinates through a square root (r from
// rho) or an arccosine, which rounds by far less.
constexpr double kRangeAltitudeTolerance_m = 1e-3;
constexpr double kRangeSunZenithTolerance_deg = 1e-6;

double degreesOfCosine(double cosine) { return degreesFromRadians(std::acos(clampCosine(cosine))); }

}  // namespace

// Tables whose sun axis reaches the domain's lowest sun go on below it to
// the nadir (the night continuation, runtime/physics/night_sky.h): every sun.
BakedRanges bakedRangesOf(const AtmosphereDomain& d) {
  const double thickness_m = d.top_radius_m - d.bottom_radius_m;
  const double high_m = d.radiusAtDistanceToHorizon(d.scattering_rho_max_m) - d.bottom_radius_m;
  return {
      d.radiusAtDistanceToHorizon(d.scattering_rho_min_m) - d.bottom_radius_m,
      high_m >= thickness_m - kRangeAltitudeTolerance_m ? std::numeric_limits<double>::infinity() : high_m,
      d.scattering_mu_s_coord_max >= 1.0 ? 0.0 : degreesOfCosine(muSFromUnitCoord(d, d.scattering_mu_s_coord_max)),
      d.scattering_mu_s_coord_min <= 0.0 ? 180.0 : degreesOfCosine(muSFromUnitCoord(d, d.scattering_mu_s_coord_min)),
      thickness_m};
}

namespace {

// A spectral bake's lane groups as ordinary Skies, their tables moved out
// of `bake`, which keeps the file's contents and, for the night
// continuation its sampler needs, the first group's (small) irradiance
// table. Empty for any other bake.
std::vector<std::shared_ptr<const Sky>> laneGroupSkies(BakeFile& bake) {
  std::vector<std::shared_ptr<const Sky>> groups;
  if (bake.contents.lane_groups.empty()) return groups;
  for (size_t g = 0; g < bake.contents.lane_groups.size(); ++g) {
    groups.push_back(std::make_shared<const Sky>(takeLaneGroup(bake, g)));
  }
  bake.lane_group_tables.clear();
  bake.tables = {};
  bake.tables.irradiance = groups.front()->tables().irradiance;
  return groups;
}

// Sky::channelLuminanceWeights: every channel's, a spectral atmosphere's
// from all its wavelengths together.
std::vector<float> channelLuminanceWeightsOf(const AtmosphereParameters& a) {
  if (a.storesLaneGroups()) return colour::wavelengthLuminanceWeights(a.wavelengths_nm);
  const Spectrum lanes = colour::luminanceWeights(a);
  return std::vector<float>(&lanes[0], &lanes[0] + a.channelCount());
}

}  // namespace

bool BakedRanges::containsAltitude(double altitude_m) const {
  altitude_m = std::clamp(altitude_m, 0.0, atmosphere_top_m);
  return altitude_m >= altitude_min_m - kRangeAltitudeTolerance_m &&
         altitude_m <= altitude_max_m + kRangeAltitudeTolerance_m;
}

bool BakedRanges::containsSunZenith(double sun_zenith_deg) const {
  return sun_zenith_deg >= sun_zenith_min_deg - kRangeSunZenithTolerance_deg &&
         sun_zenith_deg <= sun_zenith_max_deg + kRangeSunZenithTolerance_deg;
}

Sky Sky::load(const std::filesystem::path& path) { return Sky(readBakeFile(path)); }

Sky::Sky(BakeFile bake)
    : lane_groups_(laneGroupSkies(bake)),
      bake_(std::move(bake)),
      // A spectral bake's channels are wavelengths, as its file says.
      channels_{bake_.contents.atmosphere.storesLaneGroups() ? ChannelKind::Wavelengths
                                                             : bake_.contents.atmosphere.channel_kind,
                channelNames(bake_.contents.atmosphere), bake_.contents.atmosphere.wavelengths_nm},
      channel_luminance_weights_(channelLuminanceWeightsOf(bake_.contents.atmosphere)),
      luminance_weights_(colour::luminanceWeights(bake_.contents.atmosphere)),
      sampler_(bake_.contents.domain, bake_.contents.sizes,
               nightContinuationOf(bake_.contents.domain, bake_.tables.irradiance)),
      // A spectral Sky's lookups are its groups': its own shape is never used.
      multiple_shape_(lane_groups_.empty() ? bake_.contents.atmosphere : lane_groups_.front()->atmosphere(),
                      kStoredShapeOrder, bake_.contents.multiple_shape_weight),
      mie_phase_(bake_.contents.atmosphere.mie_phase_g),
      ranges_(bakedRangesOf(sampler_.domain())),
      baked_mu_s_min_(std::cos(radiansFromDegrees(ranges_.sun_zenith_max_deg))),
      baked_mu_s_max_(std::cos(radiansFromDegrees(ranges_.sun_zenith_min_deg))),
      wavelength_groups_to_xyz_(wavelengthGroupsToXyzOf(bake_.contents)) {}

double Sky::luminance(const Spectrum& value) const {
  requireOneLaneGroup("luminance(Spectrum)");
  double sum = 0.0;
  for (int c = 0; c < channelCount(); ++c) sum += static_cast<double>(luminance_weights_[c]) * value[c];
  return sum;
}

SunlitRay Sky::withBakedSun(const SunlitRay& ray) const {
  SunlitRay baked = ray;
  baked.mu_s = std::clamp(ray.mu_s, baked_mu_s_min_, baked_mu_s_max_);
  return baked;
}

double Sky::integratedSingleScatteringWeightAt(double mu_s) const {
  SunlitRay ray{};
  ray.mu_s = mu_s;
  return integratedSingleScatteringWeight(withBakedSun(ray).mu_s);
}

}  // namespace skybake
