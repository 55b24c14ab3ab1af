// TOML -> BakeConfig. Every key the user writes is either understood or
// rejected: a misspelt key silently ignored would bake the wrong sky.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "data_formats/config/config.h"
#include "data_formats/config/config_table.h"
#include "data_formats/config/toml_text_check.h"
#include "data_formats/config/toml_value_text.h"
#include "data_formats/error.h"
#include "data_formats/input_file.h"
#include "data_formats/spectra/spectral_samples.h"
#include "data_formats/spectra/spectrum_csv.h"

namespace skybake {
namespace {

// The forms a per-wavelength key accepts besides a list and a tabulated
// spectrum (CONFIG.md, "Spectra").
enum class PowerLawForm {
  None,
  Exponent,          // { at_nm, value, exponent = 4 }: Rayleigh's lambda^-4
  AngstromExponent,  // { at_nm, value, angstrom_exponent }: aerosols
};

// Rayleigh scattering by molecules much smaller than the wavelength goes as
// lambda^-4; the default of rayleigh.scattering's `exponent`.
constexpr double kRayleighExponent = 4.0;

// The per-wavelength quantities of a config, one value per wavelength of
// channels.wavelengths_nm.
struct SpectralQuantities {
  std::vector<double> ground_albedo, sun_irradiance, rayleigh_scattering, mie_scattering, mie_extinction,
      absorption_extinction;
};

// Lanes 0.. of the atmosphere's quantities from wavelengths first .. first + count - 1.
void setLanes(AtmosphereParameters& a, const SpectralQuantities& q, size_t first, size_t count) {
  auto lanes = [&](const std::vector<double>& values) {
    Spectrum s(0.0f);
    for (size_t c = 0; c < count; ++c) s[static_cast<int>(c)] = static_cast<float>(values[first + c]);
    return s;
  };
  a.ground_albedo = lanes(q.ground_albedo);
  a.sun_irradiance = lanes(q.sun_irradiance);
  a.rayleigh_scattering = lanes(q.rayleigh_scattering);
  a.mie_scattering = lanes(q.mie_scattering);
  a.mie_extinction = lanes(q.mie_extinction);
  a.absorption_extinction = lanes(q.absorption_extinction);
}

// A colour or spectral bake's passes: its wavelengths in order, kMaxChannels at a time
// (the last group holds the rest), each an ordinary per-wavelength
// atmosphere of the same shape.
std::vector<AtmosphereParameters> colourGroups(const AtmosphereParameters& colour, const SpectralQuantities& q) {
  std::vector<AtmosphereParameters> groups;
  const size_t n = colour.wavelengths_nm.size();
  for (size_t first = 0; first < n; first += kMaxChannels) {
    const size_t count = std::min<size_t>(kMaxChannels, n - first);
    AtmosphereParameters g = colour;
    g.channel_kind = ChannelKind::Wavelengths;
    g.wavelengths_nm.assign(colour.wavelengths_nm.begin() + static_cast<std::ptrdiff_t>(first),
                            colour.wavelengths_nm.begin() + static_cast<std::ptrdiff_t>(first + count));
    setLanes(g, q, first, count);
    groups.push_back(std::move(g));
  }
  return groups;
}

class ConfigReader {
 public:
  ConfigReader(std::string source, std::filesystem::path spectrum_directory)
      : source_(std::move(source)), spectrum_directory_(std::move(spectrum_directory)) {}

  [[noreturn]] void fail(const toml::node* node, const std::string& key, const std::string& value,
                         const std::string& reason) const {
    std::string where = source_;
    if (node != nullptr && node->source().begin.line > 0) {
      where += fmt::format(":{}", node->source().begin.line);
    }
    if (value.empty()) throwBadInput(fmt::format("{}: {}: {}", where, key, reason));
    throwBadInput(fmt::format("{}: {} = {}: {}", where, key, value, reason));
  }

  void rejectUnknownKeys(const toml::table& table, const std::string& prefix,
                         std::initializer_list<std::string_view> known) const {
    for (const auto& [key, node] : table) {
      bool ok = false;
      for (auto k : known) ok = ok || (key.str() == k);
      if (!ok) {
        fail(&node, prefix + std::string(key.str()), "", "unknown key");
      }
    }
  }

  const toml::table* table(const toml::table& parent, const std::string& prefix, std::string_view key,
                           bool required) const {
    const toml::node* node = parent.get(key);
    const std::string name = prefix + std::string(key);
    if (node == nullptr) {
      if (required) fail(nullptr, name, "", "missing required table");
      return nullptr;
    }
    if (!node->is_table()) fail(node, name, describe(*node), "must be a table");
    return node->as_table();
  }

  double number(const toml::node& node, const std::string& name) const {
    double value = 0.0;
    if (auto f = node.as_floating_point()) {
      value = f->get();
    } else if (auto i = node.as_integer()) {
      value = static_cast<double>(i->get());
    } else {
      fail(&node, name, describe(node), "must be a number");
    }
    if (!std::isfinite(value)) fail(&node, name, describe(node), "must be finite");
    return value;
  }

  // Returns false when absent and not required.
  bool number(const toml::table& t, const std::string& prefix, std::string_view key, bool required, double& out) const {
    const toml::node* node = t.get(key);
    if (node == nullptr) {
      if (required) fail(nullptr, prefix + std::string(key), "", "missing required key");
      return false;
    }
    out = number(*node, prefix + std::string(key));
    return true;
  }

  int integer(const toml::node& node, const std::string& name) const {
    auto i = node.as_integer();
    if (!i) fail(&node, name, describe(node), "must be an integer");
    const int64_t v = i->get();
    if (v < -1000000000 || v > 1000000000) fail(&node, name, describe(node), "out of range");
    return static_cast<int>(v);
  }

  std::vector<double> numbers(const toml::node& node, const std::string& name) const {
    auto array = node.as_array();
    if (!array) fail(&node, name, describe(node), "must be an array of numbers");
    std::vector<double> out;
    for (size_t i = 0; i < array->size(); ++i) {
      out.push_back(number(*array->get(i), fmt::format("{}[{}]", name, i)));
    }
    return out;
  }

  // The bake's wavelengths: a list of numbers, or { min_nm, max_nm, count }
  // evenly spaced with both ends included. Refuses more than a wavelength
  // bake holds as channels, or, for a colour or spectral bake, more than it
  // bakes.
  std::vector<double> wavelengths(const toml::node& node, const std::string& name, ChannelKind kind) const {
    auto refuseTooMany = [&](size_t count) {
      if (kind == ChannelKind::CieXyz) {
        if (count <= static_cast<size_t>(kMaxColourWavelengths)) return;
        fail(&node, name, describe(node),
             fmt::format("{} wavelengths, but a colour bake (channels.store = \"cie_xyz\") integrates at most {}",
                         count, kMaxColourWavelengths));
      }
      if (kind == ChannelKind::Spectral) {
        if (count <= static_cast<size_t>(kMaxSpectralWavelengths)) return;
        fail(&node, name, describe(node),
             fmt::format("{} wavelengths, but a spectral bake (channels.store = \"spectral\") stores at most {}", count,
                         kMaxSpectralWavelengths));
      }
      if (count <= static_cast<size_t>(kMaxChannels)) return;
      fail(&node, name, describe(node),
           fmt::format("{} wavelengths, but a wavelength bake holds at most {}: store them all with "
                       "channels.store = \"spectral\" (up to {}, baked {} at a time), or integrate them into "
                       "X, Y, Z with channels.store = \"cie_xyz\"",
                       count, kMaxChannels, kMaxSpectralWavelengths, kMaxChannels));
    };
    std::vector<double> out;
    if (const toml::table* range = node.as_table()) {
      rejectUnknownKeys(*range, name + ".", {"min_nm", "max_nm", "count"});
      double min_nm = 0.0, max_nm = 0.0;
      number(*range, name + ".", "min_nm", true, min_nm);
      number(*range, name + ".", "max_nm", true, max_nm);
      const toml::node* count_node = range->get("count");
      if (count_node == nullptr) fail(range, name + ".count", "", "missing required key");
      const int count = integer(*count_node, name + ".count");
      if (count < 2) {
        fail(count_node, name + ".count", describe(*count_node),
             "must be at least 2 (list a single wavelength as [nm])");
      }
      if (!(min_nm > 0.0 && min_nm < max_nm)) {
        fail(&node, name, describe(node), "needs 0 < min_nm < max_nm");
      }
      // Before the wavelengths are made: a count of a billion would not fit in memory.
      refuseTooMany(static_cast<size_t>(count));
      out = evenlySpacedWavelengths(min_nm, max_nm, count);
    } else {
      out = numbers(node, name);
      if (out.empty()) fail(&node, name, describe(node), "needs at least one wavelength");
    }
    refuseTooMany(out.size());
    return out;
  }

  // A per-wavelength quantity, one value per wavelength of the bake: a list
  // (one number per wavelength, in their order) or a table giving a spectrum
  // that is read at each wavelength (CONFIG.md, "Spectra"). Absent: the
  // fallback, or an error when required.
  std::vector<double> spectrum(const toml::table& t, const std::string& prefix, std::string_view key, bool required,
                               const std::vector<double>& wavelengths_nm, const std::vector<double>& fallback,
                               PowerLawForm power_law = PowerLawForm::None, bool cross_section = false) const {
    const toml::node* node = t.get(key);
    const std::string name = prefix + std::string(key);
    if (node == nullptr) {
      if (required) fail(nullptr, name, "", "missing required key");
      return fallback;
    }
    return perWavelength(*node, name, wavelengths_nm, power_law, cross_section);
  }

  std::vector<double> perWavelength(const toml::node& node, const std::string& name,
                                    const std::vector<double>& wavelengths_nm, PowerLawForm power_law,
                                    bool cross_section) const {
    const toml::table* form = node.as_table();
    if (form == nullptr) {
      std::vector<double> values = numbers(node, name);
      if (values.size() != wavelengths_nm.size()) {
        fail(&node, name, describe(node),
             fmt::format("needs {} values, one per wavelength in channels.wavelengths_nm", wavelengths_nm.size()));
      }
      return values;
    }
    const std::string p = name + ".";
    std::vector<double> out(wavelengths_nm.size());
    if (form->contains("at_nm") && power_law != PowerLawForm::None) {
      const char* exponent_key = power_law == PowerLawForm::Exponent ? "exponent" : "angstrom_exponent";
      rejectUnknownKeys(*form, p, {"at_nm", "value", exponent_key});
      double at_nm = 0.0, value = 0.0, exponent = kRayleighExponent;
      number(*form, p, "at_nm", true, at_nm);
      number(*form, p, "value", true, value);
      number(*form, p, exponent_key, power_law == PowerLawForm::AngstromExponent, exponent);
      if (!(at_nm > 0.0)) fail(form->get("at_nm"), p + "at_nm", describe(*form->get("at_nm")), "must be > 0");
      for (size_t c = 0; c < out.size(); ++c) out[c] = powerLaw(at_nm, value, exponent, wavelengths_nm[c]);
      return out;
    }
    // A tabulated spectrum from a file or inline, times a number density
    // for a cross-section file.
    TabulatedSpectrum table;
    std::string table_name;  // the file, or the key of an inline spectrum, in messages
    double factor = 1.0;
    if (form->contains("spectrum_csv")) {
      rejectUnknownKeys(*form, p, {"spectrum_csv", "band_nm"});
      table = spectrumFile(*form, p + "spectrum_csv", table_name);
    } else if (form->contains("cross_section_csv") && cross_section) {
      rejectUnknownKeys(*form, p, {"cross_section_csv", "number_density_m3", "band_nm"});
      table = spectrumFile(*form, p + "cross_section_csv", table_name);
      number(*form, p, "number_density_m3", true, factor);
      if (factor < 0.0) {
        fail(form->get("number_density_m3"), p + "number_density_m3", describe(*form->get("number_density_m3")),
             "must be >= 0");
      }
    } else if (form->contains("values") || form->contains("wavelengths_nm")) {
      rejectUnknownKeys(*form, p, {"wavelengths_nm", "values", "band_nm"});
      table = inlineSpectrum(*form, p);
      table_name = p + "wavelengths_nm";
    } else {
      std::string forms =
          "a list of one number per wavelength, { spectrum_csv = \"file.csv\" }, "
          "{ wavelengths_nm = [...], values = [...] }";
      if (power_law == PowerLawForm::Exponent) forms += ", { at_nm, value, exponent }";
      if (power_law == PowerLawForm::AngstromExponent) forms += ", { at_nm, value, angstrom_exponent }";
      if (cross_section) forms += ", { cross_section_csv = \"file.csv\", number_density_m3 }";
      fail(&node, name, describe(node), "must be " + forms);
    }
    double band_nm = 0.0;
    const bool banded = number(*form, p, "band_nm", false, band_nm);
    if (banded && !(band_nm > 0.0)) {
      fail(form->get("band_nm"), p + "band_nm", describe(*form->get("band_nm")), "must be > 0");
    }
    for (size_t c = 0; c < out.size(); ++c) {
      const double lambda = wavelengths_nm[c];
      const double low = banded ? lambda - 0.5 * band_nm : lambda;
      const double high = banded ? lambda + 0.5 * band_nm : lambda;
      if (!table.covers(low, high)) {
        const std::string what =
            banded ? fmt::format("the band {} to {} nm around channels.wavelengths_nm[{}] = {}", low, high, c, lambda)
                   : fmt::format("channels.wavelengths_nm[{}] = {} nm", c, lambda);
        fail(&node, name, "",
             fmt::format("{}: {} is outside its {} to {} nm (spectra are not extrapolated)", table_name, what,
                         table.firstWavelength_nm(), table.lastWavelength_nm()));
      }
      out[c] = factor * (banded ? table.bandMean(low, high) : table.at(lambda));
    }
    return out;
  }

  // The spectrum file a key names, relative to the config's directory.
  TabulatedSpectrum spectrumFile(const toml::table& form, const std::string& key, std::string& shown_name) const {
    const toml::node* node = form.get(key.substr(key.rfind('.') + 1));
    const auto text = node->as_string();
    if (!text || text->get().empty()) fail(node, key, describe(*node), "must be a file name");
    const std::filesystem::path path = spectrum_directory_ / std::filesystem::path(text->get());
    shown_name = path.string();
    spectrum_files_.push_back(path);
    try {
      return readSpectrumCsv(path);
    } catch (const Error& e) {
      fail(node, key, "", e.what());
    }
  }

  TabulatedSpectrum inlineSpectrum(const toml::table& form, const std::string& p) const {
    TabulatedSpectrum table;
    const toml::node* wl = form.get("wavelengths_nm");
    const toml::node* values = form.get("values");
    if (wl == nullptr) fail(&form, p + "wavelengths_nm", "", "missing required key");
    if (values == nullptr) fail(&form, p + "values", "", "missing required key");
    table.wavelengths_nm = numbers(*wl, p + "wavelengths_nm");
    table.values = numbers(*values, p + "values");
    if (table.values.size() != table.wavelengths_nm.size()) {
      fail(values, p + "values", describe(*values),
           fmt::format("needs {} values, one per entry of {}wavelengths_nm", table.wavelengths_nm.size(), p));
    }
    if (table.wavelengths_nm.size() < 2) {
      fail(wl, p + "wavelengths_nm", describe(*wl), "needs at least 2 samples to interpolate between");
    }
    for (size_t i = 0; i < table.wavelengths_nm.size(); ++i) {
      if (!(table.wavelengths_nm[i] > 0.0)) {
        fail(wl, fmt::format("{}wavelengths_nm[{}]", p, i), fmt::format("{}", table.wavelengths_nm[i]), "must be > 0");
      }
      if (i > 0 && !(table.wavelengths_nm[i] > table.wavelengths_nm[i - 1])) {
        fail(wl, fmt::format("{}wavelengths_nm[{}]", p, i), fmt::format("{}", table.wavelengths_nm[i]),
             fmt::format("{} {}wavelengths_nm[{}]: wavelengths must increase",
                         table.wavelengths_nm[i] == table.wavelengths_nm[i - 1] ? "repeats" : "is below", p, i - 1));
      }
    }
    return table;
  }

  DensityProfile density(const toml::table& t, const std::string& prefix) const {
    const std::string name = prefix + "density";
    const toml::node* node = t.get("density");
    if (node == nullptr) fail(nullptr, name, "", "missing required key");
    auto array = node->as_array();
    if (!array) fail(node, name, describe(*node), "must be an array of layer tables");
    DensityProfile profile;
    for (size_t i = 0; i < array->size(); ++i) {
      const std::string layer_name = fmt::format("{}[{}]", name, i);
      auto layer_table = array->get(i)->as_table();
      if (!layer_table) {
        fail(array->get(i), layer_name, describe(*array->get(i)), "must be a table");
      }
      rejectUnknownKeys(*layer_table, layer_name + ".",
                        {"width_m", "exp_term", "exp_scale", "linear_term", "constant_term"});
      DensityLayer layer;
      const std::string p = layer_name + ".";
      number(*layer_table, p, "width_m", false, layer.width_m);
      number(*layer_table, p, "exp_term", false, layer.exp_term);
      number(*layer_table, p, "exp_scale", false, layer.exp_scale);
      number(*layer_table, p, "linear_term", false, layer.linear_term);
      number(*layer_table, p, "constant_term", false, layer.constant_term);
      profile.push_back(layer);
    }
    return profile;
  }

  static std::string describe(const toml::node& node) { return tomlValueText(node); }

 private:
  std::string source_;
  std::filesystem::path spectrum_directory_;

 public:
  // Every spectrum file read (BakeConfig::input_files); reading one is not a
  // change of the reader's state that its callers see.
  mutable std::vector<std::filesystem::path> spectrum_files_;
};

}  // namespace

BakeConfig parseConfig(std::string_view toml_text, const std::string& source,
                       const std::filesystem::path& spectrum_directory) {
  checkTomlCharacters(toml_text, source);
  toml::table root;
  try {
    root = toml::parse(toml_text, source);
  } catch (const toml::parse_error& e) {
    throwBadInput(fmt::format("{}:{}:{}: TOML syntax error: {}", source, e.source().begin.line, e.source().begin.column,
                              std::string(e.description())));
  }
  return parseConfigTable(root, source, spectrum_directory);
}

BakeConfig parseConfigTable(const toml::table& root, const std::string& source,
                            const std::filesystem::path& spectrum_directory) {
  const ConfigReader in(source, spectrum_directory);
  in.rejectUnknownKeys(
      root, "", {"name", "channels", "planet", "sun", "rayleigh", "mie", "absorption", "resolution", "bake", "scene"});
  BakeConfig config;
  AtmosphereParameters& a = config.atmosphere;

  if (const toml::node* name = root.get("name")) {
    auto s = name->as_string();
    if (!s) in.fail(name, "name", ConfigReader::describe(*name), "must be a string");
    config.name = s->get();
  }

  const toml::table* channels = in.table(root, "", "channels", true);
  in.rejectUnknownKeys(*channels, "channels.", {"wavelengths_nm", "store"});
  if (const toml::node* store = channels->get("store")) {
    const auto text = store->as_string();
    const char* kExpected =
        "must be \"wavelengths\" (one channel per wavelength, at most 4), \"spectral\" (one channel per "
        "wavelength, up to 64, baked 4 at a time) or \"cie_xyz\" (X, Y, Z)";
    if (!text) in.fail(store, "channels.store", ConfigReader::describe(*store), kExpected);
    if (text->get() == "cie_xyz") {
      a.channel_kind = ChannelKind::CieXyz;
    } else if (text->get() == "spectral") {
      a.channel_kind = ChannelKind::Spectral;
    } else if (text->get() != "wavelengths") {
      in.fail(store, "channels.store", ConfigReader::describe(*store), kExpected);
    }
  }
  const toml::node* wl = channels->get("wavelengths_nm");
  if (wl == nullptr) in.fail(nullptr, "channels.wavelengths_nm", "", "missing required key");
  a.wavelengths_nm = in.wavelengths(*wl, "channels.wavelengths_nm", a.channel_kind);
  const std::vector<double>& n = a.wavelengths_nm;
  const std::vector<double> zeros(n.size(), 0.0);
  SpectralQuantities q;

  const toml::table* planet = in.table(root, "", "planet", true);
  in.rejectUnknownKeys(*planet, "planet.", {"bottom_radius_m", "top_radius_m", "ground_albedo"});
  in.number(*planet, "planet.", "bottom_radius_m", true, a.bottom_radius_m);
  in.number(*planet, "planet.", "top_radius_m", true, a.top_radius_m);
  q.ground_albedo = in.spectrum(*planet, "planet.", "ground_albedo", false, n, zeros);

  const toml::table* sun = in.table(root, "", "sun", true);
  in.rejectUnknownKeys(*sun, "sun.", {"irradiance", "angular_radius_rad", "max_zenith_deg"});
  q.sun_irradiance = in.spectrum(*sun, "sun.", "irradiance", true, n, zeros);
  a.sun_angular_radius_rad = 0.004675;
  in.number(*sun, "sun.", "angular_radius_rad", false, a.sun_angular_radius_rad);
  in.number(*sun, "sun.", "max_zenith_deg", false, a.sun_max_zenith_deg);

  q.rayleigh_scattering = q.mie_scattering = q.mie_extinction = q.absorption_extinction = zeros;
  if (const toml::table* t = in.table(root, "", "rayleigh", false)) {
    in.rejectUnknownKeys(*t, "rayleigh.", {"scattering", "density"});
    q.rayleigh_scattering = in.spectrum(*t, "rayleigh.", "scattering", true, n, zeros, PowerLawForm::Exponent);
    a.rayleigh_density = in.density(*t, "rayleigh.");
  }
  if (const toml::table* t = in.table(root, "", "mie", false)) {
    in.rejectUnknownKeys(*t, "mie.", {"scattering", "extinction", "phase_g", "density"});
    q.mie_scattering = in.spectrum(*t, "mie.", "scattering", true, n, zeros, PowerLawForm::AngstromExponent);
    q.mie_extinction =
        in.spectrum(*t, "mie.", "extinction", false, n, q.mie_scattering, PowerLawForm::AngstromExponent);
    in.number(*t, "mie.", "phase_g", true, a.mie_phase_g);
    a.mie_density = in.density(*t, "mie.");
  }
  if (const toml::table* t = in.table(root, "", "absorption", false)) {
    in.rejectUnknownKeys(*t, "absorption.", {"extinction", "density"});
    q.absorption_extinction = in.spectrum(*t, "absorption.", "extinction", true, n, zeros, PowerLawForm::None, true);
    a.absorption_density = in.density(*t, "absorption.");
  }
  if (a.storesCieXyz() || a.storesLaneGroups()) {
    config.colour_groups = colourGroups(a, q);
  } else {
    setLanes(a, q, 0, n.size());
  }

  if (const toml::table* t = in.table(root, "", "resolution", false)) {
    in.rejectUnknownKeys(*t, "resolution.", {"transmittance", "irradiance", "scattering", "scene", "iteration"});
    TextureSizes& s = config.sizes;
    auto pair = [&](std::string_view key, int& first, int& second) {
      const toml::node* node = t->get(key);
      if (node == nullptr) return;
      const std::string name = "resolution." + std::string(key);
      auto array = node->as_array();
      if (!array || array->size() != 2) {
        in.fail(node, name, ConfigReader::describe(*node), "must be an array of 2 integers");
      }
      first = in.integer(*array->get(0), name + "[0]");
      second = in.integer(*array->get(1), name + "[1]");
    };
    pair("transmittance", s.transmittance_mu, s.transmittance_r);
    pair("irradiance", s.irradiance_mu_s, s.irradiance_r);
    if (const toml::table* sc = in.table(*t, "resolution.", "scattering", false)) {
      in.rejectUnknownKeys(*sc, "resolution.scattering.", {"r", "mu", "mu_s", "nu"});
      auto size = [&](std::string_view key, int& out) {
        if (const toml::node* node = sc->get(key)) {
          out = in.integer(*node, "resolution.scattering." + std::string(key));
        }
      };
      size("r", s.scattering_r);
      size("mu", s.scattering_mu);
      size("mu_s", s.scattering_mu_s);
      size("nu", s.scattering_nu);
    }
    // An axis left out is chosen by the bake (TextureSizes::kChosenByTheBake).
    auto sizes4d = [&](const char* key, std::optional<std::array<int, 4>>& out) {
      const toml::table* table = in.table(*t, "resolution.", key, false);
      if (table == nullptr) return;
      const std::string prefix = "resolution." + std::string(key) + ".";
      in.rejectUnknownKeys(*table, prefix, {"r", "mu", "mu_s", "nu"});
      std::array<int, 4> sizes;
      sizes.fill(TextureSizes::kChosenByTheBake);
      const char* keys[4] = {"r", "mu", "mu_s", "nu"};
      for (int i = 0; i < 4; ++i) {
        if (const toml::node* node = table->get(keys[i])) sizes[i] = in.integer(*node, prefix + keys[i]);
      }
      out = sizes;
    };
    sizes4d("scene", s.scene);
    sizes4d("iteration", s.iteration);
  }

  if (const toml::table* t = in.table(root, "", "bake", false)) {
    in.rejectUnknownKeys(*t, "bake.",
                         {"orders", "order_tolerance", "max_orders", "precision", "stored_fraction_bits",
                          "tail_estimate", "combined_single_mie"});
    auto flag = [&](const char* key, bool& out) {
      if (const toml::node* node = t->get(key)) {
        auto b = node->as_boolean();
        if (!b) in.fail(node, std::string("bake.") + key, ConfigReader::describe(*node), "must be true or false");
        out = b->get();
      }
    };
    flag("tail_estimate", config.bake.tail_estimate);
    flag("combined_single_mie", config.bake.combined_single_mie);
    if (const toml::node* orders = t->get("orders")) {
      const auto text = orders->as_string();
      if (text && text->get() == "auto") {
        config.bake.auto_orders = true;
      } else if (text) {
        in.fail(orders, "bake.orders", ConfigReader::describe(*orders), "must be a whole number or \"auto\"");
      } else {
        config.bake.orders = in.integer(*orders, "bake.orders");
      }
    }
    if (const toml::node* tolerance = t->get("order_tolerance")) {
      config.bake.order_tolerance = in.number(*tolerance, "bake.order_tolerance");
    }
    if (const toml::node* cap = t->get("max_orders")) {
      config.bake.max_orders = in.integer(*cap, "bake.max_orders");
    }
    if (const toml::node* bits = t->get("stored_fraction_bits")) {
      config.bake.stored_fraction_bits = in.integer(*bits, "bake.stored_fraction_bits");
    }
    if (const toml::node* precision = t->get("precision")) {
      auto s = precision->as_string();
      const std::string value = ConfigReader::describe(*precision);
      if (!s) in.fail(precision, "bake.precision", value, "must be \"float\" or \"half\"");
      if (s->get() == "float") {
        config.bake.precision = StoragePrecision::Float;
      } else if (s->get() == "half") {
        config.bake.precision = StoragePrecision::Half;
      } else {
        in.fail(precision, "bake.precision", value, "must be \"float\" or \"half\"");
      }
    }
  }

  if (const toml::table* t = in.table(root, "", "scene", false)) {
    in.rejectUnknownKeys(*t, "scene.", {"outputs", "altitude_range_m", "sun_zenith_range_deg", "views_below_horizon"});
    if (const toml::node* node = t->get("views_below_horizon")) {
      auto b = node->as_boolean();
      if (!b) in.fail(node, "scene.views_below_horizon", ConfigReader::describe(*node), "must be true or false");
      config.scene_ranges.views_below_horizon = b->get();
    }
    auto range = [&](std::string_view key, std::optional<std::array<double, 2>>& out) {
      const toml::node* node = t->get(key);
      if (node == nullptr) return;
      const std::string name = "scene." + std::string(key);
      const std::vector<double> values = in.numbers(*node, name);
      if (values.size() != 2) in.fail(node, name, ConfigReader::describe(*node), "must be [low, high]");
      out = std::array<double, 2>{values[0], values[1]};
    };
    range("altitude_range_m", config.scene_ranges.altitude_m);
    range("sun_zenith_range_deg", config.scene_ranges.sun_zenith_deg);
    if (const toml::node* outputs = t->get("outputs")) {
      const char* kExpected = "must be a list of \"sky_radiance\", \"radiance_to_points\", \"ground_irradiance\"";
      const toml::array* list = outputs->as_array();
      if (list == nullptr) in.fail(outputs, "scene.outputs", ConfigReader::describe(*outputs), kExpected);
      bool sky_radiance = false;
      config.scene.radiance_to_points = false;
      config.scene.ground_irradiance = false;
      for (const toml::node& item : *list) {
        const auto name = item.as_string();
        if (!name) in.fail(&item, "scene.outputs", ConfigReader::describe(item), kExpected);
        if (name->get() == "sky_radiance") {
          sky_radiance = true;
        } else if (name->get() == "radiance_to_points") {
          config.scene.radiance_to_points = true;
        } else if (name->get() == "ground_irradiance") {
          config.scene.ground_irradiance = true;
        } else {
          in.fail(&item, "scene.outputs", ConfigReader::describe(item), kExpected);
        }
      }
      if (!sky_radiance) {
        in.fail(outputs, "scene.outputs", ConfigReader::describe(*outputs),
                "must include \"sky_radiance\": the other outputs are built on its tables");
      }
    }
  }

  config.input_files = in.spectrum_files_;
  validateConfig(config, source);
  return config;
}

BakeConfig loadConfigFile(const std::filesystem::path& path) {
  BakeConfig config = parseConfig(readConfigFile(path), path.string(), path.parent_path());
  config.input_files.insert(config.input_files.begin(), path);
  return config;
}

std::string readConfigFile(const std::filesystem::path& path) {
  return readInputFile(path, "config file", kMaxConfigFileBytes);
}

}  // namespace skybake
