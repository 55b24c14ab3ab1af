// Refusal of colour and spectral bakes by the verbs that compare a bake
// channel by channel with the reference solver, which computes spectral
// radiance at wavelengths: a colour bake's X, Y, Z are integrals over
// wavelength, and its atmosphere's X, Y, Z coefficients are means that no
// reference wavelength has (docs/COLOUR_BAKES.md); the reference solves at
// most 4 wavelengths at a time, a spectral bake's lane group.
#pragma once

#include <string>

#include <fmt/format.h>

#include "data_formats/atmosphere_parameters.h"
#include "data_formats/error.h"

namespace skybake::cli {

// Throws Error(BadInput) naming `source` and `verb` for a spectral bake or
// config (channels.store = "spectral"; a file of more than 4 wavelengths).
inline void requireOneLaneGroup(const AtmosphereParameters& a, const std::string& source, const char* verb) {
  if (!a.storesLaneGroups()) return;
  throwBadInput(fmt::format(
      "{}: a spectral bake of {} wavelengths (channels.store = \"spectral\"): skybake {} takes at most 4 "
      "wavelength channels, as many as the reference solver computes at once; {} the same atmosphere on at most "
      "4 of the wavelengths (channels.store = \"wavelengths\"), or its colour as a colour bake (channels.store = "
      "\"cie_xyz\", skybake validate --colour-config)",
      source, a.wavelengths_nm.size(), verb, std::string(verb) == "reference" ? "compute the reference of" : verb));
}

// Throws Error(BadInput) naming `source` and `verb` for a colour or spectral bake or config.
inline void requireWavelengthChannels(const AtmosphereParameters& a, const std::string& source, const char* verb) {
  requireOneLaneGroup(a, source, verb);
  if (!a.storesCieXyz()) return;
  throwBadInput(
      fmt::format("{}: a colour bake (channels.store = \"cie_xyz\"): skybake {} compares wavelength "
                  "channels with the reference solver; bake its wavelengths with channels.store = "
                  "\"wavelengths\" (at most 4 per file) to compare them",
                  source, verb));
}

}  // namespace skybake::cli
