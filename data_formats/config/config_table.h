// A config given as a TOML table already built in memory (the Python
// module's dicts), read by the same reader as a config file's text.
#pragma once

#include <filesystem>
#include <string>

#include <toml++/toml.h>

#include "data_formats/config/config.h"

namespace skybake {

// parseConfig without the text: the same keys, checks and messages. A
// message names `source` and the key's full path ("config dict: mie.g:
// unknown key"), and a line only for nodes that came from text. The caller
// keeps the table within kMaxTomlNesting levels (toml_text_check.h), as
// checkTomlCharacters does for text.
BakeConfig parseConfigTable(const toml::table& root, const std::string& source,
                            const std::filesystem::path& spectrum_directory = {});

}  // namespace skybake
