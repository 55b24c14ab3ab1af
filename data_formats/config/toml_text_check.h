// A character check of config text made before toml++ parses it.
//
// toml++ 3.3 (Debian 12's) reaches __builtin_unreachable, undefined
// behaviour, when it asks whether one of many non-ASCII code points (U+00A1 to
// U+0499 among them) is whitespace. It asks outside strings and comments,
// where TOML allows no non-ASCII characters anyway, after a backslash in a
// multi-line basic string, and of the first character after a line-ending
// backslash there. Refusing those few inputs first keeps every config away
// from that code.
//
// The same pass refuses nesting deeper than a config can need (32 levels of
// tables, dotted keys, arrays and inline tables): toml++ parses and frees
// nested values by recursion, and 50000 levels overflowed its stack.
#pragma once

#include <string>
#include <string_view>

namespace skybake {

// The deepest nesting a config may have: tables within tables through dotted
// keys, table headers, inline tables and arrays, counted together. toml++
// parses and destroys a nested value by recursion, one stack frame or more
// per level, so a key nested 50000 levels deep (100 kB of text) overflowed
// the stack (8000 levels with a 1 MB thread stack). skybake's own keys go 4
// levels deep at most (a density layer: a table in an array of a table).
inline constexpr int kMaxTomlNesting = 32;

// Throws Error(BadInput) "<source>:<line>:<column>: TOML syntax error: ..."
// for a non-ASCII character outside strings and comments or right after a
// backslash in a multi-line basic string (neither is valid TOML), and for one
// of the misread code points starting the text after a line-ending backslash
// there, and for nesting deeper than 32 levels. Everything else, malformed
// TOML included, is left for the parser.
void checkTomlCharacters(std::string_view text, const std::string& source);

}  // namespace skybake
