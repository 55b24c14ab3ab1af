// Reading, checking and writing bake configs (TOML). data_formats/CONFIG.md
// documents every key.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "data_formats/config/atmosphere_parameters.h"

namespace skybake {

// Limits validateConfig enforces that the command line's overrides share.
// More orders than this is a typo: real atmospheres converge in tens.
inline constexpr int kMaxOrders = 1000;
// Automatic orders: below 1e-9 float sums cannot resolve the last order's
// share (it would never stop before the cap); above 0.5 "converged" would
// mean the last order still doubled the sky.
inline constexpr double kMinOrderTolerance = 1e-9;
inline constexpr double kMaxOrderTolerance = 0.5;

// Parses TOML text. `source` names the text in error messages (a file name).
// Spectrum files the config names (CONFIG.md, "Spectra") are found relative
// to `spectrum_directory` (empty: the current directory); the config that
// comes back holds the values they resolve to, not the files.
// Throws Error(BadInput) naming source, line, key, value and reason for syntax
// errors, unknown or missing keys, wrong types and non-finite numbers, then
// runs validateConfig.
BakeConfig parseConfig(std::string_view toml_text, const std::string& source,
                       const std::filesystem::path& spectrum_directory = {});

// Reads and parses a config file; its spectrum files are relative to its
// directory. The file must be a regular file of at most kMaxConfigFileBytes
// (input_file.h): a device, pipe or huge file is refused before it is read.
BakeConfig loadConfigFile(const std::filesystem::path& path);

// A config written by hand, even with measured spectra inline (90 000
// samples, about 2 MiB), is far smaller than this; a larger file is not a
// config (a log, a device's output, binary data) and is refused before it
// is read into memory.
inline constexpr std::uintmax_t kMaxConfigFileBytes = 16u << 20;

// The text of a config file, checked as loadConfigFile checks it.
std::string readConfigFile(const std::filesystem::path& path);

// Checks physical sense: top > bottom, non-negative coefficients, |g| < 1,
// sizes in range, ... Throws Error(BadInput) "<source>: <key> = <value>: <reason>".
void validateConfig(const BakeConfig& config, const std::string& source);

// The canonical TOML of a config: every key written, numbers in shortest
// round-trip form, so parseConfig(configToToml(c)) == c exactly.
std::string configToToml(const BakeConfig& config);

// Bruneton's Earth (data_formats/presets/earth.toml, compiled in).
BakeConfig builtinEarthConfig();

}  // namespace skybake
