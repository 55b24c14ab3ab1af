// The physical description of an atmosphere and the settings of one bake, in
// SI units (metres, m^-1, radians, W m^-2 nm^-1). Filled by the config parser
// (config_parse.cpp) or the built-in Earth, checked by validateConfig.
#pragma once

#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "data_formats/angles.h"
#include "data_formats/bake_file/stored_float_bits.h"
#include "data_formats/spectra/spectrum.h"

namespace skybake {

// One layer of a density profile: the value at altitude h (metres above the
// ground) is exp_term * exp(exp_scale * h) + linear_term * h + constant_term,
// clamped to [0, 1].
struct DensityLayer {
  double width_m = 0.0;        // thickness; the last layer reaches the top
  double exp_term = 0.0;       // dimensionless
  double exp_scale = 0.0;      // m^-1
  double linear_term = 0.0;    // m^-1
  double constant_term = 0.0;  // dimensionless
  bool operator==(const DensityLayer&) const = default;
};

// Layers stacked from the ground up. Empty means density 0 everywhere.
using DensityProfile = std::vector<DensityLayer>;

// What a bake's channels hold ([channels] store in CONFIG.md, skybake:channels
// in FORMAT.md).
enum class ChannelKind {
  // One channel per wavelength (1 to kMaxChannels): spectral radiance,
  // W m^-2 sr^-1 nm^-1.
  Wavelengths,
  // Three channels X, Y, Z: the spectrum through the bake's wavelengths
  // (piecewise linear, runtime/colour/spectral_to_xyz.h) integrated against
  // the CIE 1931 colour-matching functions over nm, so radiance in
  // W m^-2 sr^-1 and 683 * Y is luminance in cd m^-2.
  CieXyz,
  // One channel per wavelength, 1 to kMaxSpectralWavelengths, stored in lane
  // groups of at most kMaxChannels (BakeConfig::colour_groups,
  // BakeContents::lane_groups): each group an ordinary atmosphere of those
  // wavelengths, baked as one pass. The file's channels are wavelengths
  // (FORMAT.md, "Spectral bakes"); a file of at most kMaxChannels of them
  // reads back as Wavelengths.
  Spectral,
};

// The most wavelengths a colour bake integrates: 64 covers 360 to 830 nm
// every 7.5 nm, finer than the smooth sky spectra need (Bruneton uses 15,
// CalcMySky 16), while the bake's time (one pass per 4 wavelengths) stays
// bounded: 16 passes of a 3-wavelength bake.
inline constexpr int kMaxColourWavelengths = 64;

// The span a colour bake's wavelengths must reach: its shortest at most
// kColourSpanShortest_nm, its longest at least kColourSpanLongest_nm.
// Beyond its end wavelengths a colour bake holds the end values
// (runtime/colour/spectral_to_xyz.h), so wavelengths that stop short of
// the colour-matching functions' lobes make the sky the colour of its end
// samples: 700 to 780 nm, or a single wavelength, turns a blue sky grey
// (CIEDE2000 above 20; 700 to 780 nm also makes it 68 % too dark). Between
// these ends lies at least 90 % of each of xbar, ybar and zbar's integral,
// and holding the end values beyond them costs a daylight sky (sunlight and
// Rayleigh-blue skylight, the sun a few degrees up or higher) at most 0.2 % of its luminance
// and 0.5 CIEDE2000, half a just noticeable difference; 10 nm less at
// either end breaks the 90 % (tests/runtime/colour_span_test.cpp).
inline constexpr double kColourSpanShortest_nm = 420.0;
inline constexpr double kColourSpanLongest_nm = 640.0;

// The most wavelengths a spectral bake (channels.store = "spectral") stores:
// the colour bake's limit, since both run one pass per 4 wavelengths.
inline constexpr int kMaxSpectralWavelengths = kMaxColourWavelengths;

// The XYZ channels of a colour bake.
inline constexpr int kCieXyzChannels = 3;

struct AtmosphereParameters {
  // Wavelengths: the channels' wavelengths, 1..kMaxChannels, in channel
  // order. CieXyz: the wavelengths integrated into X, Y, Z (1 to
  // kMaxColourWavelengths); the per-channel quantities below then hold
  // effective X, Y, Z values (runtime/colour/colour_bake_atmosphere.h).
  // Spectral: every channel's wavelength (1 to kMaxSpectralWavelengths); the
  // per-channel quantities below are 0 (laneCount() is 0), each wavelength's
  // values live in its lane group.
  std::vector<double> wavelengths_nm;
  ChannelKind channel_kind = ChannelKind::Wavelengths;

  double bottom_radius_m = 0.0;  // planet surface
  double top_radius_m = 0.0;     // top of the atmosphere
  Spectrum ground_albedo{0.0f};  // Lambertian, dimensionless

  Spectrum sun_irradiance{0.0f};  // W m^-2 nm^-1 at the top of the atmosphere
  double sun_angular_radius_rad = 0.0;
  // The lowest sun the scattering tables cover. Kept in degrees, as the config
  // key is, so that configs round-trip exactly; use sunMuSMin() in physics.
  double sun_max_zenith_deg = 111.0;

  Spectrum rayleigh_scattering{0.0f};  // m^-1 where density = 1
  DensityProfile rayleigh_density;
  Spectrum mie_scattering{0.0f};  // m^-1 where density = 1
  Spectrum mie_extinction{0.0f};  // m^-1 where density = 1, >= scattering
  double mie_phase_g = 0.0;       // Cornette-Shanks asymmetry
  DensityProfile mie_density;
  Spectrum absorption_extinction{0.0f};  // m^-1 where density = 1
  DensityProfile absorption_density;

  int channelCount() const {
    return channel_kind == ChannelKind::CieXyz ? kCieXyzChannels : static_cast<int>(wavelengths_nm.size());
  }
  // The lanes of the Spectrum quantities below that hold values: the
  // channels, except for a spectral atmosphere, whose values are its lane
  // groups' (none here).
  int laneCount() const { return channel_kind == ChannelKind::Spectral ? 0 : channelCount(); }
  bool storesCieXyz() const { return channel_kind == ChannelKind::CieXyz; }
  bool storesLaneGroups() const { return channel_kind == ChannelKind::Spectral; }
  // Cosine of sun_max_zenith_deg: the mu_s at the low end of the scattering domain.
  double sunMuSMin() const { return std::cos(radiansFromDegrees(sun_max_zenith_deg)); }
  bool operator==(const AtmosphereParameters&) const = default;
};

// A per-channel quantity's values of `groups`' lanes one after the other:
// each wavelength's value, in wavelength order, for the wavelength groups
// of a colour or spectral bake.
inline std::vector<double> groupLaneValues(const std::vector<AtmosphereParameters>& groups,
                                           Spectrum AtmosphereParameters::*quantity) {
  std::vector<double> values;
  for (const AtmosphereParameters& g : groups) {
    for (int l = 0; l < g.laneCount(); ++l) values.push_back((g.*quantity)[l]);
  }
  return values;
}

// Texel counts. Transmittance and irradiance are 2D (mu or mu_s across, r
// down); scattering is 4D (r, mu, mu_s, nu).
struct TextureSizes {
  // An axis of resolution.scene or resolution.iteration left to the bake.
  static constexpr int kChosenByTheBake = 0;
  int transmittance_mu = 256;
  int transmittance_r = 64;
  int irradiance_mu_s = 81;  // 0.45 x 80 = 36 intervals below the horizon: a texel on it
  int irradiance_r = 16;
  int scattering_r = 32;
  int scattering_mu = 128;  // even: half for rays that hit the ground
  int scattering_mu_s = 41;
  int scattering_nu = 16;
  // [resolution] scene and iteration, each r, mu, mu_s and nu: for a
  // [scene] that narrows the domain, the 4D sizes of the stored tables on
  // the scene's ranges, and those the orders iterate on over the whole
  // domain. Absent, or an axis of them 0 (kChosenByTheBake): chosen from the
  // scattering sizes above, which are then the whole domain's
  // (settledBakeConfig in baker/bake/bake_policy.h). Unused without scene
  // ranges (which the command line can add to a config).
  std::optional<std::array<int, 4>> scene;
  std::optional<std::array<int, 4>> iteration;
  // Texels of one 4D scattering table at these sizes.
  double scatteringTexels() const { return 1.0 * scattering_r * scattering_mu * scattering_mu_s * scattering_nu; }
  bool operator==(const TextureSizes&) const = default;
};

enum class StoragePrecision { Float, Half };

struct BakeSettings {
  int orders = 6;  // scattering orders: 1 = single scattering only
  // orders = "auto": compute orders until the last one adds less than
  // order_tolerance of the total so far (mean radiance over the scattering
  // table, worst channel), at most max_orders. Optically thick atmospheres
  // need tens of orders; Earth's clear sky converges to 1e-3 in about 8.
  bool auto_orders = false;
  double order_tolerance = 1e-3;
  int max_orders = 64;
  // Half: each 4D table's (r, mu_s) slice scaled by a power of two and
  // rounded to half (data_formats/bake_file/half_slices.h), half the file of float at
  // a rounding 10 times below the tables' interpolation error.
  StoragePrecision precision = StoragePrecision::Half;
  // The fraction bits the file keeps of every FLOAT value but the optical
  // depths' (stored_float_bits.h): kFloatFractionBits keeps them all.
  int stored_fraction_bits = kDefaultStoredFractionBits;
  // Add the orders after the last as a geometric series (see BakeReport).
  bool tail_estimate = true;
  // Store single Mie scattering as one channel (the first wavelength's) beside
  // single Rayleigh scattering, and rebuild the other channels from the
  // Rayleigh channels' spectral shape (approximateSingleMie in bake_file.h):
  // the file loses all but one channel of the single_mie part, the sky gains
  // an approximation error (docs/LEAVE_OUT.md). Needs a free channel (at
  // most 3 wavelengths) and Rayleigh and Mie scattering in the first one.
  bool combined_single_mie = false;
};

// What the scene uses of the bake ([scene] in CONFIG.md). The tables of an
// output it does not use are left out of the file. Sky radiance is always
// baked: the other outputs are built on its tables.
struct SceneOutputs {
  // Sky::radianceToPoint (aerial perspective): the multiple-scattering density table.
  bool radiance_to_points = true;
  // Sky::irradiance, and the lit ground in Sky::receivedRadiance: the sky
  // irradiance table (computed anyway, since higher orders need it).
  bool ground_irradiance = true;

  bool all() const { return radiance_to_points && ground_irradiance; }
  bool operator==(const SceneOutputs&) const = default;
};

// The cameras and suns the scene has ([scene] in CONFIG.md): the 4D tables
// cover only these ranges, so their texels all go where the scene looks.
// Unset: the whole atmosphere, every sun up to sun.max_zenith_deg.
struct SceneRanges {
  // Altitudes above the ground of the cameras and of the points they look
  // at (radiance to a point), metres: [low, high].
  std::optional<std::array<double, 2>> altitude_m;
  // Sun zenith angles, degrees: [low, high], high <= sun.max_zenith_deg.
  std::optional<std::array<double, 2>> sun_zenith_deg;
  // Whether the 4D tables hold rays that end on the ground. Without them the
  // tables' whole mu axis holds the sky; lookups of rays toward the ground
  // integrate along the ray instead (Sky).
  bool views_below_horizon = true;

  bool narrows() const { return altitude_m.has_value() || sun_zenith_deg.has_value() || !views_below_horizon; }
};

struct BakeConfig {
  std::string name = "custom";
  // A colour bake (atmosphere.channel_kind CieXyz): wavelengths_nm and the
  // shape of the atmosphere as parsed; its X, Y, Z quantities are filled by
  // settledBakeConfig from the groups below (baker/bake/bake_policy.h).
  AtmosphereParameters atmosphere;
  // A colour or spectral bake's wavelengths in groups of at most
  // kMaxChannels, in the order of atmosphere.wavelengths_nm, each an ordinary
  // per-wavelength atmosphere that the bake runs as one pass; empty otherwise.
  std::vector<AtmosphereParameters> colour_groups;
  TextureSizes sizes;
  BakeSettings bake;
  SceneOutputs scene;
  SceneRanges scene_ranges;
  // The files the config was read from: its own file and every spectrum
  // file it names (empty for a config parsed from text alone). Not part of
  // the bake; an output must never replace one of them (requireWritableOutput).
  std::vector<std::filesystem::path> input_files;
};

}  // namespace skybake
