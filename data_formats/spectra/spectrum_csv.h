// Spectrum files for configs (CONFIG.md, "Spectra"): two columns, wavelength
// in nm and a value, one sample a line.
#pragma once

#include <filesystem>

#include "data_formats/spectra/spectral_samples.h"

namespace skybake {

// Reads a spectrum CSV: lines "wavelength_nm,value" (blanks around cells
// allowed, CRLF line ends and a leading UTF-8 byte-order mark too); '#' lines and blank lines are skipped; the
// first other line may be a header of two names. Throws Error(BadInput)
// "<path>:<line>: <value>: <reason>" for a line that is not two finite
// numbers and for a wavelength that is not above the line before it
// (unsorted or repeated), "<path>: <reason>" for a file that cannot be read,
// is not a regular file, is too large or holds fewer than 2 samples.
TabulatedSpectrum readSpectrumCsv(const std::filesystem::path& path);

}  // namespace skybake
