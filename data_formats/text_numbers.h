// Numbers in text files (query CSVs, spectrum CSVs): one rule for what a
// number cell is and what surrounds it, shared by every reader.
#pragma once

#include <charconv>
#include <cmath>
#include <string_view>
#include <system_error>

namespace skybake {

// The byte-order mark some spreadsheets put before a file's first line.
inline constexpr std::string_view kUtf8ByteOrderMark = "\xEF\xBB\xBF";

// Blanks around a cell; '\r' is the rest of a CRLF line end.
inline constexpr std::string_view kCellBlanks = " \t\r";

inline std::string_view trimmedCell(std::string_view text) {
  const size_t first = text.find_first_not_of(kCellBlanks);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(kCellBlanks) - first + 1);
}

// Whether `text` is a whole finite number (what a data cell must be).
inline bool parseFiniteNumber(std::string_view text, double& value) {
  const char* begin = text.data();
  const char* end = begin + text.size();
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  return !text.empty() && ec == std::errc() && ptr == end && std::isfinite(value);
}

}  // namespace skybake
