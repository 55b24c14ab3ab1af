// Refusal of colour bakes by the verbs that compare a bake channel by
// channel with the reference solver, which computes spectral radiance at
// wavelengths: a colour bake's X, Y, Z are integrals over wavelength, and
// its atmosphere's X, Y, Z coefficients are means that no reference
// wavelength has (docs/COLOUR_BAKES.md).
#pragma once

#include <string>

#include <fmt/format.h>

#include "data_formats/atmosphere_parameters.h"
#include "data_formats/error.h"

namespace skybake::cli {

// Throws Error(BadInput) naming `source` and `verb` for a colour bake or config.
inline void requireWavelengthChannels(const AtmosphereParameters& a, const std::string& source, const char* verb) {
  if (!a.storesCieXyz()) return;
  throwBadInput(
      fmt::format("{}: a colour bake (channels.store = \"cie_xyz\"): skybake {} compares wavelength "
                  "channels with the reference solver; bake its wavelengths with channels.store = "
                  "\"wavelengths\" (at most 4 per file) to compare them",
                  source, verb));
}

}  // namespace skybake::cli
