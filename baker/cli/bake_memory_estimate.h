// The memory a bake needs, from its config alone, so that a bake too large
// for the machine is refused before anything is allocated.
#pragma once

#include <cstdint>
#include <string>

#include "data_formats/config/atmosphere_parameters.h"

namespace skybake {

struct BakeMemoryEstimate {
  uint64_t table_4d_bytes = 0;        // one table of the scattering table's size
  int tables_4d_at_peak = 0;          // how many of them are alive at once at the peak
  uint64_t density_table_bytes = 0;   // one table of the density's size (half the view texels)
  int density_tables_at_peak = 0;     // how many of them are alive at once at the peak
  uint64_t order_radiance_bytes = 0;  // beside them, the orders' radiance on its smaller tables
  uint64_t density_kernel_bytes = 0;  // the scattering-density stage's phase modes (orders >= 2)
  uint64_t peak_bytes = 0;            // every table alive at the peak, 4D and 2D, and the kernel
  uint64_t kept_bytes = 0;            // the tables the finished bake keeps (its file's)
};

// Table memory at the peak of bakeAtmosphere for `config`'s sizes and
// orders (automatic orders: up to bake.max_orders). Every texel is a
// Spectrum (kMaxChannels floats) whatever the channel count. Products that
// would overflow 64 bits saturate at UINT64_MAX instead of wrapping round to
// a small number. The process's own code and libraries are not included.
// A colour bake adds its X, Y, Z sums beside one pass; a spectral bake keeps
// every pass's tables, so its kept_bytes is the passes' and its peak holds
// the earlier passes' tables beside the running one's.
BakeMemoryEstimate estimateBakeMemory(const BakeConfig& config);

// Core-seconds a bake of `config` takes, estimated from its 4D table's texels
// and its orders (automatic: up to bake.max_orders), the stages' cost per
// texel and order as measured (kBakeCoreSecondsPerTexelOrder). An estimate
// for job time limits, not a promise: other machines and loads differ.
double estimateBakeCoreSeconds(const BakeConfig& config);

// Throws Error(BadInput), naming `source` (the config's file or origin), its
// scattering sizes and the estimate, when the bake of `config` needs more
// memory than this process may allocate (available_memory.h).
void requireMemoryForBake(const BakeConfig& config, const std::string& source);

}  // namespace skybake
