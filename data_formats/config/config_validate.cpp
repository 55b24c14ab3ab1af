// Physical and practical limits on a config. Each check names the key, the
// value and why it is refused.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "data_formats/angles.h"
#include "data_formats/bake_file/bake_file.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

// Planet radii outside this range are not planets skybake can bake: below a
// metre the float texture coordinates lose all resolution, above 1e10 m (a
// hundred solar radii) the distances overflow float precision in the runtime.
constexpr double kMinPlanetRadius_m = 1.0;
constexpr double kMaxPlanetRadius_m = 1.0e10;
// The sun's angular radius: beyond 0.5 rad the small-disk approximation of the
// direct irradiance falls apart.
constexpr double kMaxSunAngularRadius_rad = 0.5;
// The lowest sun the scattering table covers, as a zenith angle: below 20 deg
// there is no domain left to tabulate, above 180 deg is not an angle.
constexpr double kMinSunMaxZenith_deg = 20.0;
constexpr double kMaxSunMaxZenith_deg = 180.0;
// Texture sizes: below 2 texels per axis nothing can be interpolated; the upper
// bounds keep a single table below a few GiB.
constexpr int kMin2DSize = 2;
constexpr int kMax2DSize = 8192;
constexpr int kMax4DAxis = 1024;
constexpr long long kMaxScatteringTexels = 1LL << 28;  // 4 GiB of float4
// The tables are float (largest 3.4e38). The optical depth along the longest
// ray through the atmosphere (the chord along the ground's horizon, both
// ways) is stored and summed: a coefficient of 3e38 m^-1 made it infinite,
// and the bake wrote a file its own reader refuses. 1e20 is far beyond any
// atmosphere (Venus's horizontal optical depth is ~1e4) and leaves float
// room for the sums.
constexpr double kMaxOpticalDepth = 1e20;
// Sun irradiance, W m^-2 nm^-1: radiance tables hold it times scattering
// integrals and phase functions, densities times coefficients too. 1e15
// times the Sun's at Earth keeps those products inside float.
constexpr double kMaxSunIrradiance = 1e15;
// The sun disk's radiance, irradiance over the disk's solid angle
// (Sky::solarRadiance): a tiny disk of a bright sun would overflow float.
constexpr double kMaxSunRadiance = 1e30;

class Checker {
 public:
  explicit Checker(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const std::string& key, const std::string& value, const std::string& reason) const {
    throwBadInput(fmt::format("{}: {} = {}: {}", source_, key, value, reason));
  }

  void finite(const std::string& key, double v) const {
    if (!std::isfinite(v)) fail(key, fmt::format("{}", v), "must be finite");
  }

  void nonNegative(const std::string& key, const Spectrum& s, int channels) const {
    for (int c = 0; c < channels; ++c) {
      finite(fmt::format("{}[{}]", key, c), s[c]);
      if (s[c] < 0.0f) fail(fmt::format("{}[{}]", key, c), fmt::format("{}", s[c]), "must be >= 0");
    }
  }

  void range(const std::string& key, double v, double lo, double hi) const {
    finite(key, v);
    if (v < lo || v > hi) fail(key, fmt::format("{}", v), fmt::format("must be in [{}, {}]", lo, hi));
  }

  void profile(const std::string& key, const DensityProfile& layers) const {
    for (size_t i = 0; i < layers.size(); ++i) {
      const std::string p = fmt::format("{}.density[{}].", key, i);
      const DensityLayer& l = layers[i];
      finite(p + "width_m", l.width_m);
      if (l.width_m < 0.0) fail(p + "width_m", fmt::format("{}", l.width_m), "must be >= 0");
      finite(p + "exp_term", l.exp_term);
      finite(p + "exp_scale", l.exp_scale);
      finite(p + "linear_term", l.linear_term);
      finite(p + "constant_term", l.constant_term);
    }
  }

 private:
  const std::string& source_;
};

// Products of the parameters that the bake stores in float must fit it.
// Densities are clamped to [0, 1], so a coefficient bounds its constituent.
void checkFloatRange(const Checker& check, const AtmosphereParameters& a) {
  const int n = a.laneCount();
  const double chord_m = 2.0 * std::sqrt(a.top_radius_m * a.top_radius_m - a.bottom_radius_m * a.bottom_radius_m);
  for (int c = 0; c < n; ++c) {
    const struct {
      const char* key;
      float value;  // printed as the config gave it
    } parts[] = {{"rayleigh.scattering", a.rayleigh_scattering[c]},
                 {"mie.extinction", a.mie_extinction[c]},
                 {"absorption.extinction", a.absorption_extinction[c]}};
    double total = 0.0;
    const char* largest = parts[0].key;
    float largest_value = -1.0f;
    for (const auto& p : parts) {
      total += p.value;
      if (p.value > largest_value) largest = p.key, largest_value = p.value;
    }
    if (total * chord_m > kMaxOpticalDepth) {
      check.fail(fmt::format("{}[{}]", largest, c), fmt::format("{}", largest_value),
                 fmt::format("the optical depth along the longest ray through the atmosphere ({} m) would be {:.3g}, "
                             "beyond the {:g} the float tables hold",
                             chord_m, total * chord_m, kMaxOpticalDepth));
    }
    if (a.sun_irradiance[c] > kMaxSunIrradiance) {
      check.fail(fmt::format("sun.irradiance[{}]", c), fmt::format("{}", a.sun_irradiance[c]),
                 fmt::format("must be <= {:g} W m^-2 nm^-1: the radiance tables hold it times scattering "
                             "integrals, in float",
                             kMaxSunIrradiance));
    }
    const double disk_solid_angle_sr =
        4.0 * kPi * std::pow(std::sin(0.5 * a.sun_angular_radius_rad), 2);  // 2 pi (1 - cos), no cancellation
    if (a.sun_angular_radius_rad > 0.0 && a.sun_irradiance[c] > kMaxSunRadiance * disk_solid_angle_sr) {
      check.fail("sun.angular_radius_rad", fmt::format("{}", a.sun_angular_radius_rad),
                 fmt::format("too small for sun.irradiance[{}] = {}: the disk's radiance would exceed {:g} "
                             "W m^-2 sr^-1 nm^-1 (use 0 for a point sun)",
                             c, a.sun_irradiance[c], kMaxSunRadiance));
    }
  }
}

// A colour bake's wavelengths reach the colour-matching functions' lobes
// (kColourSpanShortest_nm, kColourSpanLongest_nm). Checked on configs to
// bake (those with colour_groups), not on a file's header: a file is read
// as it was baked.
void requireColourSpan(const std::vector<double>& wavelengths_nm, const Checker& check) {
  if (wavelengths_nm.empty()) return;  // refused above with its count
  const auto [shortest, longest] = std::minmax_element(wavelengths_nm.begin(), wavelengths_nm.end());
  if (*shortest <= kColourSpanShortest_nm && *longest >= kColourSpanLongest_nm) return;
  const std::string value = *shortest == *longest ? fmt::format("{} nm (one wavelength)", *shortest)
                                                  : fmt::format("{} to {} nm", *shortest, *longest);
  check.fail("channels.wavelengths_nm", value,
             fmt::format("a colour bake (channels.store = \"cie_xyz\") needs wavelengths from {} nm or "
                         "shorter to {} nm or longer: beyond its end wavelengths it holds the end values, and "
                         "narrower wavelengths miss the colour-matching functions and turn the sky grey",
                         kColourSpanShortest_nm, kColourSpanLongest_nm));
}

// A colour or spectral bake's passes (BakeConfig::colour_groups), when the
// config has them (a config read back from a colour file's header has only
// its X, Y, Z atmosphere): each an ordinary atmosphere of the bake's shape,
// together its wavelengths in order.
void validateColourGroups(const BakeConfig& config, const Checker& check, const std::string& source) {
  const AtmosphereParameters& a = config.atmosphere;
  if (config.colour_groups.empty()) return;
  std::vector<double> grouped_nm;
  for (const AtmosphereParameters& g : config.colour_groups) {
    AtmosphereParameters shape = g;
    shape.channel_kind = a.channel_kind;
    shape.wavelengths_nm = a.wavelengths_nm;
    shape.ground_albedo = a.ground_albedo;
    shape.sun_irradiance = a.sun_irradiance;
    shape.rayleigh_scattering = a.rayleigh_scattering;
    shape.mie_scattering = a.mie_scattering;
    shape.mie_extinction = a.mie_extinction;
    shape.absorption_extinction = a.absorption_extinction;
    if (g.channel_kind != ChannelKind::Wavelengths || !(shape == a)) {
      throw Error(ErrorKind::Internal, fmt::format("{}: a wavelength group differs from its bake's "
                                                   "atmosphere in more than its per-wavelength quantities",
                                                   source));
    }
    grouped_nm.insert(grouped_nm.end(), g.wavelengths_nm.begin(), g.wavelengths_nm.end());
    BakeConfig pass = config;
    pass.atmosphere = g;
    pass.colour_groups.clear();
    validateConfig(pass, source);
  }
  if (grouped_nm != a.wavelengths_nm) {
    check.fail("channels.wavelengths_nm", fmt::format("{} values", a.wavelengths_nm.size()),
               "differs from the wavelengths of the bake's passes");
  }
}

}  // namespace

void validateConfig(const BakeConfig& config, const std::string& source) {
  const Checker check(source);
  const AtmosphereParameters& a = config.atmosphere;
  // Per-channel values held in the atmosphere's own lanes (a spectral
  // atmosphere's are in its groups, checked with them below).
  const int n = a.laneCount();
  const int wavelengths = static_cast<int>(a.wavelengths_nm.size());
  const int max_wavelengths = a.storesCieXyz()       ? kMaxColourWavelengths
                              : a.storesLaneGroups() ? kMaxSpectralWavelengths
                                                     : kMaxChannels;
  if (wavelengths < 1 || wavelengths > max_wavelengths) {
    check.fail("channels.wavelengths_nm", fmt::format("{} values", wavelengths),
               fmt::format("needs 1 to {} wavelengths{}", max_wavelengths,
                           a.storesCieXyz()       ? " in a colour bake (channels.store = \"cie_xyz\")"
                           : a.storesLaneGroups() ? " in a spectral bake (channels.store = \"spectral\")"
                                                  : ""));
  }
  for (int c = 0; c < wavelengths; ++c) {
    const std::string key = fmt::format("channels.wavelengths_nm[{}]", c);
    check.finite(key, a.wavelengths_nm[c]);
    if (a.wavelengths_nm[c] <= 0.0) check.fail(key, fmt::format("{}", a.wavelengths_nm[c]), "must be > 0");
    // The file names each channel by its wavelength: two equal ones would
    // share one channel, and the first came out as radiance 0.
    for (int earlier = 0; earlier < c; ++earlier) {
      if (channelName(a.wavelengths_nm[earlier]) == channelName(a.wavelengths_nm[c])) {
        check.fail(
            key, fmt::format("{}", a.wavelengths_nm[c]),
            fmt::format("repeats channels.wavelengths_nm[{}]: each channel is named by its wavelength", earlier));
      }
    }
  }

  if (a.storesCieXyz() && !config.colour_groups.empty()) requireColourSpan(a.wavelengths_nm, check);

  check.range("planet.bottom_radius_m", a.bottom_radius_m, kMinPlanetRadius_m, kMaxPlanetRadius_m);
  check.finite("planet.top_radius_m", a.top_radius_m);
  if (!(a.top_radius_m > a.bottom_radius_m)) {
    check.fail("planet.top_radius_m", fmt::format("{}", a.top_radius_m),
               fmt::format("must be greater than planet.bottom_radius_m ({})", a.bottom_radius_m));
  }
  check.range("planet.top_radius_m", a.top_radius_m, kMinPlanetRadius_m, 2.0 * kMaxPlanetRadius_m);
  check.nonNegative("planet.ground_albedo", a.ground_albedo, n);
  for (int c = 0; c < n; ++c) {
    if (a.ground_albedo[c] > 1.0f) {
      check.fail(fmt::format("planet.ground_albedo[{}]", c), fmt::format("{}", a.ground_albedo[c]),
                 "must be <= 1 (a surface cannot reflect more than it receives)");
    }
  }

  check.nonNegative("sun.irradiance", a.sun_irradiance, n);
  check.range("sun.angular_radius_rad", a.sun_angular_radius_rad, 0.0, kMaxSunAngularRadius_rad);
  check.range("sun.max_zenith_deg", a.sun_max_zenith_deg, kMinSunMaxZenith_deg, kMaxSunMaxZenith_deg);

  check.nonNegative("rayleigh.scattering", a.rayleigh_scattering, n);
  check.profile("rayleigh", a.rayleigh_density);
  check.nonNegative("mie.scattering", a.mie_scattering, n);
  check.nonNegative("mie.extinction", a.mie_extinction, n);
  for (int c = 0; c < n; ++c) {
    if (a.mie_extinction[c] < a.mie_scattering[c]) {
      check.fail(fmt::format("mie.extinction[{}]", c), fmt::format("{}", a.mie_extinction[c]),
                 fmt::format("must be >= mie.scattering[{}] ({}): extinction is scattering plus "
                             "absorption",
                             c, a.mie_scattering[c]));
    }
  }
  check.finite("mie.phase_g", a.mie_phase_g);
  if (!(std::abs(a.mie_phase_g) < 1.0)) {
    check.fail("mie.phase_g", fmt::format("{}", a.mie_phase_g), "must be in (-1, 1)");
  }
  check.profile("mie", a.mie_density);
  check.nonNegative("absorption.extinction", a.absorption_extinction, n);
  check.profile("absorption", a.absorption_density);
  checkFloatRange(check, a);

  const TextureSizes& s = config.sizes;
  auto size = [&](const std::string& key, int v, int lo, int hi) {
    if (v < lo || v > hi) {
      check.fail(key, fmt::format("{}", v), fmt::format("must be in [{}, {}]", lo, hi));
    }
  };
  size("resolution.transmittance[0]", s.transmittance_mu, kMin2DSize, kMax2DSize);
  size("resolution.transmittance[1]", s.transmittance_r, kMin2DSize, kMax2DSize);
  size("resolution.irradiance[0]", s.irradiance_mu_s, kMin2DSize, kMax2DSize);
  size("resolution.irradiance[1]", s.irradiance_r, kMin2DSize, kMax2DSize);
  size("resolution.scattering.r", s.scattering_r, 2, kMax4DAxis);
  size("resolution.scattering.mu", s.scattering_mu, 4, kMax4DAxis);
  size("resolution.scattering.mu_s", s.scattering_mu_s, 2, kMax4DAxis);
  size("resolution.scattering.nu", s.scattering_nu, 2, kMax4DAxis);
  if (s.scattering_mu % 2 != 0) {
    check.fail("resolution.scattering.mu", fmt::format("{}", s.scattering_mu),
               "must be even: half the rows hold rays that hit the ground, half those that do not");
  }
  const long long texels = 1LL * s.scattering_r * s.scattering_mu * s.scattering_mu_s * s.scattering_nu;
  if (texels > kMaxScatteringTexels) {
    check.fail("resolution.scattering", fmt::format("{} texels", texels),
               fmt::format("more than {} texels per table", kMaxScatteringTexels));
  }
  // resolution.scene and resolution.iteration: an axis may be left to the bake.
  auto sizes4d = [&](const std::string& key, const std::optional<std::array<int, 4>>& sizes) {
    if (!sizes) return;
    const std::array<int, 4>& it = *sizes;
    const char* axes[4] = {"r", "mu", "mu_s", "nu"};
    const int minimum[4] = {2, 4, 2, 2};
    for (int i = 0; i < 4; ++i) {
      if (it[i] != TextureSizes::kChosenByTheBake) size(key + "." + axes[i], it[i], minimum[i], kMax4DAxis);
    }
    if (it[1] % 2 != 0) {
      check.fail(key + ".mu", fmt::format("{}", it[1]),
                 "must be even: half the rows hold rays that hit the ground, half those that do not");
    }
    const long long texels = 1LL * it[0] * it[1] * it[2] * it[3];
    if (texels > kMaxScatteringTexels) {
      check.fail(key, fmt::format("{} texels", texels),
                 fmt::format("more than {} texels per table", kMaxScatteringTexels));
    }
  };
  sizes4d("resolution.scene", s.scene);
  sizes4d("resolution.iteration", s.iteration);

  bool has_mie = false;
  for (int c = 0; c < n; ++c) has_mie = has_mie || a.mie_scattering[c] > 0.0f;
  if (config.bake.combined_single_mie && a.storesCieXyz()) {
    check.fail("bake.combined_single_mie", "true",
               "needs wavelength channels: it rebuilds single Mie scattering from Rayleigh's spectral shape "
               "across the channels, which X, Y and Z (each a band over the whole visible range) do not have; "
               "leave it out of a colour bake (channels.store = \"cie_xyz\")");
  }
  if (config.bake.combined_single_mie && a.storesLaneGroups()) {
    check.fail("bake.combined_single_mie", "true",
               "needs a channel free beside the wavelengths for single Mie scattering, which a spectral bake "
               "(channels.store = \"spectral\") does not keep: every part holds one channel per wavelength; "
               "leave it out, or bake at most 3 wavelengths with channels.store = \"wavelengths\"");
  }
  if (a.storesCieXyz() || a.storesLaneGroups()) validateColourGroups(config, check, source);
  if (a.storesLaneGroups() && config.colour_groups.empty()) {
    throw Error(ErrorKind::Internal, fmt::format("{}: a spectral bake's config without its wavelength groups", source));
  }
  if (config.bake.combined_single_mie && has_mie) {
    if (n >= kMaxChannels) {
      check.fail("bake.combined_single_mie", "true",
                 fmt::format("needs a channel free beside the wavelengths for single Mie scattering: at most {} "
                             "wavelengths (channels.wavelengths_nm has {})",
                             kMaxChannels - 1, n));
    } else if (!(a.rayleigh_scattering[0] > 0.0f && a.mie_scattering[0] > 0.0f)) {
      check.fail("bake.combined_single_mie", "true",
                 fmt::format("needs Rayleigh and Mie scattering at the first wavelength ({} nm), whose single Mie "
                             "scattering is stored and from which the other channels are rebuilt",
                             a.wavelengths_nm[0]));
    }
  }

  if (config.bake.orders < 1 || config.bake.orders > kMaxOrders) {
    check.fail("bake.orders", fmt::format("{}", config.bake.orders), fmt::format("must be in [1, {}]", kMaxOrders));
  }
  if (!(config.bake.order_tolerance >= kMinOrderTolerance && config.bake.order_tolerance <= kMaxOrderTolerance)) {
    check.fail("bake.order_tolerance", fmt::format("{}", config.bake.order_tolerance),
               fmt::format("must be in [{}, {}]", kMinOrderTolerance, kMaxOrderTolerance));
  }
  if (config.bake.stored_fraction_bits < kMinStoredFractionBits ||
      config.bake.stored_fraction_bits > kFloatFractionBits) {
    check.fail("bake.stored_fraction_bits", fmt::format("{}", config.bake.stored_fraction_bits),
               fmt::format("must be in [{}, {}] ({} keeps every value exact; fewer than {} is coarser than "
                           "bake.precision = \"half\")",
                           kMinStoredFractionBits, kFloatFractionBits, kFloatFractionBits, kMinStoredFractionBits));
  }
  if (config.bake.max_orders < 2 || config.bake.max_orders > kMaxOrders) {
    check.fail("bake.max_orders", fmt::format("{}", config.bake.max_orders),
               fmt::format("must be in [2, {}]", kMaxOrders));
  }

  const SceneRanges& scene = config.scene_ranges;
  auto ordered = [&](const std::string& key, const std::array<double, 2>& r) {
    check.finite(key + "[0]", r[0]);
    check.finite(key + "[1]", r[1]);
    if (!(r[0] < r[1])) {
      check.fail(key, fmt::format("[{}, {}]", r[0], r[1]), "the low end must be below the high end");
    }
  };
  if (scene.altitude_m) {
    const std::array<double, 2>& r = *scene.altitude_m;
    ordered("scene.altitude_range_m", r);
    const double thickness_m = a.top_radius_m - a.bottom_radius_m;
    if (r[0] < 0.0 || r[0] >= thickness_m) {
      check.fail("scene.altitude_range_m[0]", fmt::format("{}", r[0]),
                 fmt::format("must be in [0, {}) m: from the ground to below the top of the atmosphere", thickness_m));
    }
  }
  if (scene.sun_zenith_deg) {
    const std::array<double, 2>& r = *scene.sun_zenith_deg;
    ordered("scene.sun_zenith_range_deg", r);
    if (r[0] < 0.0) check.fail("scene.sun_zenith_range_deg[0]", fmt::format("{}", r[0]), "must be >= 0");
    if (r[1] > a.sun_max_zenith_deg) {
      check.fail("scene.sun_zenith_range_deg[1]", fmt::format("{}", r[1]),
                 fmt::format("must be <= sun.max_zenith_deg ({}), the lowest sun baked", a.sun_max_zenith_deg));
    }
  }
}

}  // namespace skybake
