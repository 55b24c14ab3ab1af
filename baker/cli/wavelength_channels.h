// Refusals by the verbs that compare a bake channel by channel with the
// reference solver, which computes spectral radiance at wavelengths, at most
// 4 at a time: a colour bake's X, Y, Z are integrals over wavelength, and
// its atmosphere's X, Y, Z coefficients are means that no reference
// wavelength has (docs/COLOUR_BAKES.md). A spectral bake is validated lane
// group by lane group (baker/validation/lane_group_validation.h); only
// compare's comparators, which take one atmosphere of at most 4
// wavelengths, refuse it.
#pragma once

#include <string>

#include <fmt/format.h>

#include "data_formats/config/atmosphere_parameters.h"
#include "data_formats/error.h"

namespace skybake::cli {

// Throws Error(BadInput) naming `source` for a spectral config
// (channels.store = "spectral") given to skybake compare without --colour.
inline void requireOneLaneGroupForComparators(const AtmosphereParameters& a, const std::string& source) {
  if (!a.storesLaneGroups()) return;
  throwBadInput(fmt::format(
      "{}: a spectral bake of {} wavelengths (channels.store = \"spectral\"): skybake compare's comparators take at "
      "most 4 wavelengths; measure the spectral bake's error per wavelength with skybake validate (each lane group "
      "of 4 against its own reference), compare the same atmosphere on at most 4 of the wavelengths "
      "(channels.store = \"wavelengths\"), or its colour with skybake compare --colour on its colour bake's config "
      "(channels.store = \"cie_xyz\")",
      source, a.wavelengths_nm.size()));
}

// Throws Error(BadInput) naming `source` and `verb` for a colour bake or config.
inline void requireWavelengthChannels(const AtmosphereParameters& a, const std::string& source, const char* verb) {
  if (!a.storesCieXyz()) return;
  throwBadInput(
      fmt::format("{}: a colour bake (channels.store = \"cie_xyz\"): skybake {} compares wavelength "
                  "channels with the reference solver; bake its wavelengths with channels.store = "
                  "\"wavelengths\" (at most 4 per file) or \"spectral\" to compare them",
                  source, verb));
}

}  // namespace skybake::cli
