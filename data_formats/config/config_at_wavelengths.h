// A config read at wavelengths other than its own: the same atmosphere, its
// per-wavelength quantities taken from the config's own spectra (CONFIG.md,
// "Spectra") at the wavelengths asked for. The colour reference of
// `skybake validate --colour-config` evaluates a bake's atmosphere this way
// at 41 wavelengths from 380 to 780 nm, a few at a time. Also a config on its
// own wavelengths stored another way (channels.store).
#pragma once

#include <array>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "data_formats/config/atmosphere_parameters.h"
#include "data_formats/config/config.h"

namespace skybake {

// The per-wavelength keys of a config, as written in TOML.
inline constexpr std::array<std::string_view, 6> kPerWavelengthConfigKeys = {
    "planet.ground_albedo", "sun.irradiance", "rayleigh.scattering",
    "mie.scattering",       "mie.extinction", "absorption.extinction"};

// Parses `toml_text` (as parseConfig does, spectrum files relative to
// `spectrum_directory`) with channels.wavelengths_nm replaced by
// `wavelengths_nm` (1 to kMaxChannels of them), stored as wavelengths (a
// colour bake's channels.store is dropped). A per-wavelength key given as
// a list of one number per wavelength says nothing between its wavelengths:
// it is refused with Error(BadInput) naming source, key and value, unless
// every number of the list is the same (a flat spectrum, such as a grey
// ground albedo, is that number at every wavelength). Spectra that do not
// cover a wavelength are refused by the parser, naming the key and the file.
BakeConfig configAtWavelengths(std::string_view toml_text, const std::string& source,
                               const std::filesystem::path& spectrum_directory, std::span<const double> wavelengths_nm);

// The same for a config file (its spectrum files relative to its directory).
BakeConfig configFileAtWavelengths(const std::filesystem::path& path, std::span<const double> wavelengths_nm);

// The config file with channels.store set to `store` ("wavelengths",
// "cie_xyz" or "spectral"): the same atmosphere on the same wavelengths,
// stored another way (skybake compare --colour puts a colour bake's config
// beside its spectral bake). Refused as a config file is (Error(BadInput)
// naming the file and the store) where the store cannot take it.
BakeConfig configFileWithStore(const std::filesystem::path& path, std::string_view store);

}  // namespace skybake
