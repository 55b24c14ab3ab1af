// TOML -> BakeConfig. Every key the user writes is either understood or
// rejected: a misspelt key silently ignored would bake the wrong sky.
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "config.h"
#include "error.h"
#include "toml_text_check.h"
#include "toml_value_text.h"

namespace skybake {
namespace {

class ConfigReader {
 public:
  explicit ConfigReader(std::string source) : source_(std::move(source)) {}

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

  // A per-channel array: exactly one number per wavelength.
  Spectrum spectrum(const toml::table& t, const std::string& prefix, std::string_view key, bool required, int channels,
                    Spectrum fallback) const {
    const toml::node* node = t.get(key);
    const std::string name = prefix + std::string(key);
    if (node == nullptr) {
      if (required) fail(nullptr, name, "", "missing required key");
      return fallback;
    }
    const std::vector<double> values = numbers(*node, name);
    if (static_cast<int>(values.size()) != channels) {
      fail(node, name, describe(*node),
           fmt::format("needs {} values, one per wavelength in channels.wavelengths_nm", channels));
    }
    Spectrum s(0.0f);
    for (int c = 0; c < channels; ++c) s[c] = static_cast<float>(values[c]);
    return s;
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
};

}  // namespace

BakeConfig parseConfig(std::string_view toml_text, const std::string& source) {
  checkTomlCharacters(toml_text, source);
  toml::table root;
  try {
    root = toml::parse(toml_text, source);
  } catch (const toml::parse_error& e) {
    throwBadInput(fmt::format("{}:{}:{}: TOML syntax error: {}", source, e.source().begin.line, e.source().begin.column,
                              std::string(e.description())));
  }
  const ConfigReader in(source);
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
  in.rejectUnknownKeys(*channels, "channels.", {"wavelengths_nm"});
  const toml::node* wl = channels->get("wavelengths_nm");
  if (wl == nullptr) in.fail(nullptr, "channels.wavelengths_nm", "", "missing required key");
  a.wavelengths_nm = in.numbers(*wl, "channels.wavelengths_nm");
  const int n = static_cast<int>(a.wavelengths_nm.size());
  if (n < 1 || n > kMaxChannels) {
    in.fail(wl, "channels.wavelengths_nm", ConfigReader::describe(*wl),
            fmt::format("needs 1 to {} wavelengths (bake more in separate files)", kMaxChannels));
  }

  const toml::table* planet = in.table(root, "", "planet", true);
  in.rejectUnknownKeys(*planet, "planet.", {"bottom_radius_m", "top_radius_m", "ground_albedo"});
  in.number(*planet, "planet.", "bottom_radius_m", true, a.bottom_radius_m);
  in.number(*planet, "planet.", "top_radius_m", true, a.top_radius_m);
  a.ground_albedo = in.spectrum(*planet, "planet.", "ground_albedo", false, n, Spectrum(0.0f));

  const toml::table* sun = in.table(root, "", "sun", true);
  in.rejectUnknownKeys(*sun, "sun.", {"irradiance", "angular_radius_rad", "max_zenith_deg"});
  a.sun_irradiance = in.spectrum(*sun, "sun.", "irradiance", true, n, Spectrum(0.0f));
  a.sun_angular_radius_rad = 0.004675;
  in.number(*sun, "sun.", "angular_radius_rad", false, a.sun_angular_radius_rad);
  in.number(*sun, "sun.", "max_zenith_deg", false, a.sun_max_zenith_deg);

  if (const toml::table* t = in.table(root, "", "rayleigh", false)) {
    in.rejectUnknownKeys(*t, "rayleigh.", {"scattering", "density"});
    a.rayleigh_scattering = in.spectrum(*t, "rayleigh.", "scattering", true, n, Spectrum(0.0f));
    a.rayleigh_density = in.density(*t, "rayleigh.");
  }
  if (const toml::table* t = in.table(root, "", "mie", false)) {
    in.rejectUnknownKeys(*t, "mie.", {"scattering", "extinction", "phase_g", "density"});
    a.mie_scattering = in.spectrum(*t, "mie.", "scattering", true, n, Spectrum(0.0f));
    a.mie_extinction = in.spectrum(*t, "mie.", "extinction", false, n, a.mie_scattering);
    in.number(*t, "mie.", "phase_g", true, a.mie_phase_g);
    a.mie_density = in.density(*t, "mie.");
  }
  if (const toml::table* t = in.table(root, "", "absorption", false)) {
    in.rejectUnknownKeys(*t, "absorption.", {"extinction", "density"});
    a.absorption_extinction = in.spectrum(*t, "absorption.", "extinction", true, n, Spectrum(0.0f));
    a.absorption_density = in.density(*t, "absorption.");
  }

  if (const toml::table* t = in.table(root, "", "resolution", false)) {
    in.rejectUnknownKeys(*t, "resolution.", {"transmittance", "irradiance", "scattering", "iteration"});
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
    if (const toml::table* it = in.table(*t, "resolution.", "iteration", false)) {
      in.rejectUnknownKeys(*it, "resolution.iteration.", {"r", "mu", "mu_s", "nu"});
      const TextureSizes defaults;
      std::array<int, 4> sizes{defaults.scattering_r, defaults.scattering_mu, defaults.scattering_mu_s,
                               defaults.scattering_nu};
      const char* keys[4] = {"r", "mu", "mu_s", "nu"};
      for (int i = 0; i < 4; ++i) {
        if (const toml::node* node = it->get(keys[i])) {
          sizes[i] = in.integer(*node, "resolution.iteration." + std::string(keys[i]));
        }
      }
      s.iteration = sizes;
    }
  }

  if (const toml::table* t = in.table(root, "", "bake", false)) {
    in.rejectUnknownKeys(
        *t, "bake.", {"orders", "order_tolerance", "max_orders", "precision", "tail_estimate", "combined_single_mie"});
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

  validateConfig(config, source);
  return config;
}

BakeConfig loadConfigFile(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throwBadInput(fmt::format("{}: cannot open config file", path.string()));
  std::ostringstream text;
  text << file.rdbuf();
  return parseConfig(text.str(), path.string());
}

}  // namespace skybake
