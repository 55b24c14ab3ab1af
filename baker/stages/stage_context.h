// What every bake stage works with: the atmosphere, the sampler that says
// where the tables' texels are, and where progress goes. Each stage fills a
// table from earlier tables; each texel is computed independently, so the
// result does not depend on how texels are spread over threads.
#pragma once

#include "baker/stages/progress.h"
#include "data_formats/config/atmosphere_parameters.h"
#include "runtime/tables/table_sampler.h"

namespace skybake {

struct StageContext {
  const AtmosphereParameters& atmosphere;
  const TableSampler& sampler;
  ProgressSink& progress;
};

}  // namespace skybake
