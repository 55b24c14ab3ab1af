// A spectral bake (channels.store = "spectral"): many wavelengths, every one
// stored. Baked in passes of at most 4, each pass an ordinary
// bakeWavelengthPass whose tables are kept as they are (each divided by its
// own pass's multiple-scattering shape), so that memory holds every pass's
// tables and the file holds one channel per wavelength
// (data_formats/FORMAT.md, "Spectral bakes").
#pragma once

#include "baker/bake/bake.h"

namespace skybake {

// `settled` is a settled spectral config (settledBakeConfig): its
// colour_groups are the passes. Every pass is a complete bake of the same
// sizes and domain (automatic orders converge per pass); the file records
// the largest number of orders a pass computed. The report gives each
// stage's seconds summed over the passes, the pass count and, per order,
// what it added at each wavelength. One group gives the ordinary bake of
// its wavelengths.
BakeOutput bakeSpectral(const BakeConfig& settled, int threads, ProgressSink& progress);

}  // namespace skybake
