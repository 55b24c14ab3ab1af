// Arrays and tables are written here, element by element, instead of by
// toml++'s formatter: toml++ 3.3's formatter estimates an array's width from
// log10 of its numbers, which is undefined behaviour for a float between -1
// and 1 (a negative logarithm cast to size_t) and for the most negative
// integer (negated). Scalars, which it prints without that estimate, still go
// through toml++ so strings are quoted and escaped as TOML does.
#include "data_formats/config/toml_value_text.h"

#include <sstream>

namespace skybake {
namespace {

// Keeps one-line messages readable.
constexpr size_t kMaxShownChars = 60;

void appendValueText(const toml::node& node, std::string& out) {
  // Stop early: whatever would follow is cut anyway, and a deeply nested or
  // huge value should cost no more than the part that is shown.
  if (out.size() > kMaxShownChars) return;
  if (const toml::array* array = node.as_array()) {
    out += "[";
    for (size_t i = 0; i < array->size() && out.size() <= kMaxShownChars; ++i) {
      if (i > 0) out += ", ";
      appendValueText(*array->get(i), out);
    }
    out += "]";
    return;
  }
  if (const toml::table* table = node.as_table()) {
    out += "{ ";
    bool first = true;
    for (const auto& [key, value] : *table) {
      if (out.size() > kMaxShownChars) break;
      if (!first) out += ", ";
      first = false;
      out += std::string(key.str()) + " = ";
      appendValueText(value, out);
    }
    out += " }";
    return;
  }
  std::ostringstream scalar;
  node.visit([&](const auto& value) { scalar << value; });
  out += scalar.str();
}

}  // namespace

std::string tomlValueText(const toml::node& node) {
  std::string text;
  appendValueText(node, text);
  if (text.size() > kMaxShownChars) text = text.substr(0, kMaxShownChars) + "...";
  return text;
}

}  // namespace skybake
