// BakeConfig -> canonical TOML. Used for the file header (the parameters travel
// with the bake) and for `skybake info`. fmt's "{}" prints the shortest text
// that reads back to the same double, so the round trip is exact.
#include <fmt/format.h>

#include "data_formats/config/config.h"

namespace skybake {
namespace {

// The one control character above U+001F, which TOML strings must escape too.
constexpr char kDelete = 0x7F;

template <typename Real>  // float or double: each prints its own shortest form
std::string numberText(Real v) {
  // TOML needs a '.' or exponent to read a float back as a float.
  std::string text = fmt::format("{}", v);
  if (text.find_first_of(".eE") == std::string::npos) text += ".0";
  return text;
}

// Floats print in their own shortest form, which reads back to the same float.
std::string spectrumList(const Spectrum& s, int n) {
  std::string out = "[";
  for (int c = 0; c < n; ++c) out += fmt::format("{}{}", c ? ", " : "", numberText(s[c]));
  return out + "]";
}

// A per-wavelength quantity of every wavelength: the channels' lanes, or a
// colour or spectral bake's groups' lanes one after the other.
template <typename Quantity>
std::string perWavelengthList(const BakeConfig& config, Quantity quantity) {
  if (!config.atmosphere.storesCieXyz() && !config.atmosphere.storesLaneGroups()) {
    return spectrumList(quantity(config.atmosphere), config.atmosphere.channelCount());
  }
  std::string out = "[";
  bool first = true;
  for (const AtmosphereParameters& g : config.colour_groups) {
    const Spectrum s = quantity(g);
    for (int c = 0; c < g.channelCount(); ++c) {
      out += fmt::format("{}{}", first ? "" : ", ", numberText(s[c]));
      first = false;
    }
  }
  return out + "]";
}

std::string profileList(const DensityProfile& layers) {
  std::string out = "[";
  for (size_t i = 0; i < layers.size(); ++i) {
    const DensityLayer& l = layers[i];
    out += fmt::format("{}{{ width_m = {}, exp_term = {}, exp_scale = {}, linear_term = {}, constant_term = {} }}",
                       i ? ", " : "", numberText(l.width_m), numberText(l.exp_term), numberText(l.exp_scale),
                       numberText(l.linear_term), numberText(l.constant_term));
  }
  return out + "]";
}

// `resolution.scene` or `resolution.iteration` as one line, axes the bake
// chooses left out; nothing when absent.
std::string sizes4d(const char* key, const std::optional<std::array<int, 4>>& sizes) {
  if (!sizes) return std::string();
  const char* axes[4] = {"r", "mu", "mu_s", "nu"};
  std::string fields;
  for (int i = 0; i < 4; ++i) {
    if ((*sizes)[i] == TextureSizes::kChosenByTheBake) continue;
    fields += fmt::format("{}{} = {}", fields.empty() ? "" : ", ", axes[i], (*sizes)[i]);
  }
  return fmt::format("{} = {{ {} }}\n", key, fields);
}

// The [scene] table: the outputs the scene uses, sky radiance first, and the
// ranges it sets.
std::string sceneTable(const SceneOutputs& scene, const SceneRanges& ranges) {
  std::string outputs = "\"sky_radiance\"";
  if (scene.radiance_to_points) outputs += ", \"radiance_to_points\"";
  if (scene.ground_irradiance) outputs += ", \"ground_irradiance\"";
  std::string text = fmt::format("\n[scene]\noutputs = [{}]\n", outputs);
  auto range = [&](const char* key, const std::optional<std::array<double, 2>>& r) {
    if (r) text += fmt::format("{} = [{}, {}]\n", key, numberText((*r)[0]), numberText((*r)[1]));
  };
  range("altitude_range_m", ranges.altitude_m);
  range("sun_zenith_range_deg", ranges.sun_zenith_deg);
  if (!ranges.views_below_horizon) text += "views_below_horizon = false\n";
  return text;
}

}  // namespace

std::string configToToml(const BakeConfig& config) {
  const AtmosphereParameters& a = config.atmosphere;
  std::string wavelengths = "[";
  for (size_t c = 0; c < a.wavelengths_nm.size(); ++c) {
    wavelengths += fmt::format("{}{}", c ? ", " : "", numberText(a.wavelengths_nm[c]));
  }
  wavelengths += "]";
  // Written only for colour and spectral bakes, so that wavelength bakes
  // keep their canonical text (and the reference cache keys hashed from it).
  if (a.storesCieXyz()) wavelengths += "\nstore = \"cie_xyz\"";
  if (a.storesLaneGroups()) wavelengths += "\nstore = \"spectral\"";
  auto list = [&](Spectrum AtmosphereParameters::*quantity) {
    return perWavelengthList(config, [&](const AtmosphereParameters& p) { return p.*quantity; });
  };
  const TextureSizes& s = config.sizes;
  std::string name;
  for (char ch : config.name) {  // TOML basic string escaping
    if (ch == '"' || ch == '\\') name += '\\';
    // TOML forbids control characters unescaped in strings: U+0000 to U+001F
    // and DEL; a raw one would make a bake whose stored config cannot be read.
    if (static_cast<unsigned char>(ch) < 0x20 || ch == kDelete) {
      name += fmt::format("\\u{:04x}", static_cast<unsigned char>(ch));
      continue;
    }
    name += ch;
  }
  return fmt::format(
      "name = \"{}\"\n\n"
      "[channels]\nwavelengths_nm = {}\n\n"
      "[planet]\nbottom_radius_m = {}\ntop_radius_m = {}\nground_albedo = {}\n\n"
      "[sun]\nirradiance = {}\nangular_radius_rad = {}\nmax_zenith_deg = {}\n\n"
      "[rayleigh]\nscattering = {}\ndensity = {}\n\n"
      "[mie]\nscattering = {}\nextinction = {}\nphase_g = {}\ndensity = {}\n\n"
      "[absorption]\nextinction = {}\ndensity = {}\n\n"
      "[resolution]\ntransmittance = [{}, {}]\nirradiance = [{}, {}]\n"
      "scattering = {{ r = {}, mu = {}, mu_s = {}, nu = {} }}\n{}\n"
      "[bake]\norders = {}\nprecision = \"{}\"\ntail_estimate = {}\n{}{}{}{}",
      name, wavelengths, numberText(a.bottom_radius_m), numberText(a.top_radius_m),
      list(&AtmosphereParameters::ground_albedo), list(&AtmosphereParameters::sun_irradiance),
      numberText(a.sun_angular_radius_rad), numberText(a.sun_max_zenith_deg),
      list(&AtmosphereParameters::rayleigh_scattering), profileList(a.rayleigh_density),
      list(&AtmosphereParameters::mie_scattering), list(&AtmosphereParameters::mie_extinction),
      numberText(a.mie_phase_g), profileList(a.mie_density), list(&AtmosphereParameters::absorption_extinction),
      profileList(a.absorption_density), s.transmittance_mu, s.transmittance_r, s.irradiance_mu_s, s.irradiance_r,
      s.scattering_r, s.scattering_mu, s.scattering_mu_s, s.scattering_nu,
      sizes4d("scene", s.scene) + sizes4d("iteration", s.iteration),
      config.bake.auto_orders ? std::string("\"auto\"") : std::to_string(config.bake.orders),
      config.bake.precision == StoragePrecision::Half ? "half" : "float", config.bake.tail_estimate,
      // Written only when it is not the default, for the same reason as below.
      config.bake.stored_fraction_bits == kDefaultStoredFractionBits
          ? std::string()
          : fmt::format("stored_fraction_bits = {}\n", config.bake.stored_fraction_bits),
      // Written only for automatic orders, so fixed-order configs keep their
      // canonical text (and the reference cache keys hashed from it).
      config.bake.auto_orders ? fmt::format("order_tolerance = {}\nmax_orders = {}\n",
                                            numberText(config.bake.order_tolerance), config.bake.max_orders)
                              : std::string(),
      config.bake.combined_single_mie ? std::string("combined_single_mie = true\n") : std::string(),
      // Written only when the scene leaves an output out or narrows the
      // domain, for the same reason.
      config.scene.all() && !config.scene_ranges.narrows() ? std::string()
                                                           : sceneTable(config.scene, config.scene_ranges));
}

}  // namespace skybake
