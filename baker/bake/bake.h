// The order loop: from a config to every table of a bake, with timings.
#pragma once

#include "baker/bake/bake_report.h"
#include "baker/stages/progress.h"
#include "data_formats/bake_file/bake_file.h"

namespace skybake {

struct BakeOutput {
  BakeFile file;
  BakeReport report;
};

// Runs every stage for `config` on `threads` OpenMP threads (0: OpenMP's
// default). The result is identical for every thread count. The file holds
// the config as settled (settledBakeConfig, baker/bake/bake_policy.h).
// A colour bake (channels.store = "cie_xyz") runs bakeWavelengthPass once per
// group of at most 4 wavelengths and sums the tables into X, Y, Z
// (baker/bake/colour_bake.h); a spectral bake (channels.store = "spectral")
// runs it once per group and keeps every group's tables
// (baker/bake/spectral_bake.h).
BakeOutput bakeAtmosphere(const BakeConfig& config, int threads, ProgressSink& progress);

// One pass of the order loop over a settled config of 1 to 4 wavelength
// channels: what bakeAtmosphere does for a config that is not a colour bake.
BakeOutput bakeWavelengthPass(const BakeConfig& settled, int threads, ProgressSink& progress);

// The report as stored in the file header (see BakeReport::toJson).
void setStoredReport(BakeOutput& bake, bool with_run_facts);

}  // namespace skybake
