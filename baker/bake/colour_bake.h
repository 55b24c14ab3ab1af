// A colour bake (channels.store = "cie_xyz"): many wavelengths baked in
// passes of at most 4, each pass's tables summed into X, Y, Z as it ends, so
// that memory holds one pass's working tables and the XYZ sums, and the file
// is a 3-channel bake (data_formats/FORMAT.md, "Colour bakes").
#pragma once

#include "baker/bake/bake.h"

namespace skybake {

// `settled` is a settled colour config (settledBakeConfig): its atmosphere
// holds the X, Y, Z quantities, its colour_groups the passes. Every pass is a
// complete bakeWavelengthPass of the same sizes and domain (automatic orders
// converge per pass); the report gives each stage's seconds summed over the
// passes and, per order, the X, Y, Z of what the passes' orders added.
BakeOutput bakeCieXyz(const BakeConfig& settled, int threads, ProgressSink& progress);

}  // namespace skybake
