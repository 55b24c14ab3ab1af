// A TOML value as short one-line text, for error messages.
#pragma once

#include <string>

#include <toml++/toml.h>

namespace skybake {

// The value as TOML writes it, arrays and inline tables on one line, cut to
// a readable length with "..." when longer.
std::string tomlValueText(const toml::node& node);

}  // namespace skybake
