#include "data_formats/terminal_text.h"

#include <fmt/format.h>

namespace skybake {
namespace {

constexpr unsigned char kDelete = 0x7F;

// Bytes of the UTF-8 sequence led by `lead`, or 0 for a byte that cannot lead one.
size_t sequenceLength(unsigned char lead) {
  if (lead < 0x80) return 1;
  if (lead >= 0xC2 && lead <= 0xDF) return 2;
  if (lead >= 0xE0 && lead <= 0xEF) return 3;
  if (lead >= 0xF0 && lead <= 0xF4) return 4;
  return 0;
}

}  // namespace

std::string terminalSafe(std::string_view text, bool keep_line_breaks) {
  std::string out;
  out.reserve(text.size());
  auto escaped = [&](unsigned char byte) { out += fmt::format("\\x{:02x}", byte); };
  for (size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte < 0x80) {
      const bool line_break = byte == '\n' || byte == '\t';
      if ((byte < 0x20 && !(line_break && keep_line_breaks)) || byte == kDelete) {
        escaped(byte);
      } else {
        out += static_cast<char>(byte);
      }
      ++i;
      continue;
    }
    const size_t length = sequenceLength(byte);
    bool valid = length > 0 && i + length <= text.size();
    for (size_t k = 1; valid && k < length; ++k) valid = (static_cast<unsigned char>(text[i + k]) & 0xC0) == 0x80;
    // U+0080 to U+009F (C2 80 to C2 9F) are the C1 controls.
    const bool c1_control = valid && byte == 0xC2 && static_cast<unsigned char>(text[i + 1]) <= 0x9F;
    if (!valid || c1_control) {
      escaped(byte);
      ++i;
      continue;
    }
    out.append(text.substr(i, length));
    i += length;
  }
  return out;
}

std::string shownText(std::string_view text) {
  if (text.size() <= kMaxShownBytes) return terminalSafe(text);
  // Cut at a character boundary: back over UTF-8 continuation bytes.
  size_t cut = kMaxShownBytes;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return fmt::format("{}... ({} bytes)", terminalSafe(text.substr(0, cut)), text.size());
}

}  // namespace skybake
