#include "data_formats/config/config_at_wavelengths.h"

#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include "data_formats/config/toml_text_check.h"
#include "data_formats/config/toml_value_text.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

// The node at a dotted key ("table.key"), or null when absent.
toml::node* nodeAt(toml::table& root, std::string_view dotted_key) {
  const size_t dot = dotted_key.find('.');
  toml::table* table = root.get_as<toml::table>(dotted_key.substr(0, dot));
  return table == nullptr ? nullptr : table->get(dotted_key.substr(dot + 1));
}

// A list of one number per wavelength made into `count` copies of its one
// value, or refused when its values differ (or are not numbers: the parser
// then names the key at the config's own wavelengths first).
void replaceFlatList(toml::node& node, std::string_view key, const std::string& source, size_t count) {
  const toml::array* list = node.as_array();
  if (list == nullptr || list->empty()) return;
  auto valueOf = [](const toml::node& item) -> std::optional<double> {
    if (auto f = item.as_floating_point()) return f->get();
    if (auto i = item.as_integer()) return static_cast<double>(i->get());
    return std::nullopt;
  };
  const std::optional<double> first = valueOf(*list->get(0));
  if (!first) return;
  for (const toml::node& item : *list) {
    if (valueOf(item) != first) {
      std::string where = source;
      if (node.source().begin.line > 0) where += fmt::format(":{}", node.source().begin.line);
      throwBadInput(fmt::format(
          "{}: {} = {}: a list of one value per wavelength cannot be read at other wavelengths; give it as a "
          "spectrum ({{ spectrum_csv = \"file.csv\" }}, {{ wavelengths_nm = [...], values = [...] }} or a "
          "power law, CONFIG.md \"Spectra\")",
          where, key, tomlValueText(node)));
    }
  }
  toml::array flat;
  for (size_t c = 0; c < count; ++c) flat.push_back(*first);
  node.as_array()->operator=(std::move(flat));
}

}  // namespace

BakeConfig configAtWavelengths(std::string_view toml_text, const std::string& source,
                               const std::filesystem::path& spectrum_directory,
                               std::span<const double> wavelengths_nm) {
  // The config at its own wavelengths first: any error of its own is reported
  // against the text as written, with its line numbers.
  parseConfig(toml_text, source, spectrum_directory);
  checkTomlCharacters(toml_text, source);
  toml::table root = toml::parse(toml_text, source);
  toml::array wavelengths;
  for (double w : wavelengths_nm) wavelengths.push_back(w);
  toml::table& channels = *root.get_as<toml::table>("channels");
  channels.insert_or_assign("wavelengths_nm", std::move(wavelengths));
  // The atmosphere at these wavelengths, channel by channel, also for a
  // colour bake's config (which would otherwise integrate them into X, Y, Z).
  channels.erase("store");
  for (std::string_view key : kPerWavelengthConfigKeys) {
    if (toml::node* node = nodeAt(root, key)) replaceFlatList(*node, key, source, wavelengths_nm.size());
  }
  std::ostringstream text;
  text << toml::toml_formatter(root);
  return parseConfig(text.str(), fmt::format("{} (at {} nm)", source, fmt::join(wavelengths_nm, ", ")),
                     spectrum_directory);
}

BakeConfig configFileAtWavelengths(const std::filesystem::path& path, std::span<const double> wavelengths_nm) {
  return configAtWavelengths(readConfigFile(path), path.string(), path.parent_path(), wavelengths_nm);
}

BakeConfig configFileWithStore(const std::filesystem::path& path, std::string_view store) {
  const std::string toml_text = readConfigFile(path);
  // The config as written first, so that its own errors name its lines.
  parseConfig(toml_text, path.string(), path.parent_path());
  checkTomlCharacters(toml_text, path.string());
  toml::table root = toml::parse(toml_text, path.string());
  if (root.get_as<toml::table>("channels") == nullptr) root.insert_or_assign("channels", toml::table{});
  root.get_as<toml::table>("channels")->insert_or_assign("store", std::string(store));
  std::ostringstream text;
  text << toml::toml_formatter(root);
  return parseConfig(text.str(), fmt::format("{} (channels.store = \"{}\")", path.string(), store), path.parent_path());
}

}  // namespace skybake
