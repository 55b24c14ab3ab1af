// Text from files (a bake's name, its carried config, its report) made safe
// to print on a terminal: a name holding escape sequences could otherwise
// move the cursor, retitle the window or hide what follows.
#pragma once

#include <string>
#include <string_view>

namespace skybake {

// `text` with every control character (C0, DEL, and the C1 range U+0080 to
// U+009F as UTF-8) written as \xHH, bytes that are not valid UTF-8 too.
// Newlines and tabs are kept when `keep_line_breaks` (multi-line text such
// as a config).
std::string terminalSafe(std::string_view text, bool keep_line_breaks = false);

// Untrusted text as a message quotes it (a CSV cell, a dict key, a value
// from a file): terminalSafe, and cut after kMaxShownBytes with the whole
// length said ("... (62914560 bytes)"), so that a 60 MB cell is not echoed
// whole and a NUL does not cut the message short.
inline constexpr size_t kMaxShownBytes = 80;
std::string shownText(std::string_view text);

}  // namespace skybake
