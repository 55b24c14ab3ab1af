// The order loop: from a config to every table of a bake, with timings.
#pragma once

#include "baker/bake/bake_report.h"
#include "baker/stages/progress.h"
#include "data_formats/bake_file.h"

namespace skybake {

struct BakeOutput {
  BakeFile file;
  BakeReport report;
};

// Runs every stage for `config` on `threads` OpenMP threads (0: OpenMP's
// default). The result is identical for every thread count. The file holds
// the config as settled (settledBakeConfig, baker/bake/bake_policy.h).
BakeOutput bakeAtmosphere(const BakeConfig& config, int threads, ProgressSink& progress);

// The report as stored in the file header (see BakeReport::toJson).
void setStoredReport(BakeOutput& bake, bool with_run_facts);

}  // namespace skybake
