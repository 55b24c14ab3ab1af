#include "baker/cli/bake_memory_estimate.h"
#include "baker/bake/bake_policy.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

#include <fmt/format.h>

#include "baker/cli/available_memory.h"
#include "baker/stages/scattering_density_kernel.h"
#include "data_formats/parameterization/texture_mapping.h"
#include "data_formats/spectra/spectrum.h"

namespace skybake {
namespace {

constexpr uint64_t kSaturated = std::numeric_limits<uint64_t>::max();

// The product of non-negative factors, or kSaturated if it overflows.
uint64_t product(std::initializer_list<uint64_t> factors) {
  uint64_t result = 1;
  for (uint64_t f : factors) {
    if (__builtin_mul_overflow(result, f, &result)) return kSaturated;
  }
  return result;
}

uint64_t sum(std::initializer_list<uint64_t> terms) {
  uint64_t result = 0;
  for (uint64_t t : terms) {
    if (__builtin_add_overflow(result, t, &result)) return kSaturated;
  }
  return result;
}

uint64_t axis(int size) { return size > 0 ? static_cast<uint64_t>(size) : 0; }

// Order radiance tables (orderRadianceSizes) alive at once: the new one and,
// from order 3 on, the one before it, still read until it is replaced.
int orderRadianceTablesAtPeak(int orders) { return orders <= 1 ? 0 : orders == 2 ? 1 : 2; }

}  // namespace

BakeMemoryEstimate estimateBakeMemory(const BakeConfig& config) {
  const TextureSizes& s = config.sizes;
  const uint64_t texel_bytes = sizeof(Spectrum);
  const uint64_t transmittance = product({axis(s.transmittance_mu), axis(s.transmittance_r), texel_bytes});
  const uint64_t irradiance = product({axis(s.irradiance_mu_s), axis(s.irradiance_r), texel_bytes});
  BakeMemoryEstimate e;
  auto table4DBytes = [&](const TextureSizes& t) {
    return product(
        {axis(t.scattering_r), axis(t.scattering_mu), axis(t.scattering_mu_s), axis(t.scattering_nu), texel_bytes});
  };
  // The orders iterate on the whole domain's tables; a narrowing scene keeps
  // its density (the sum and the last order's) beside them and then builds
  // its other 3 stored tables.
  const TextureSizes iteration = iterationTextureSizes(config);
  const uint64_t iteration_bytes = table4DBytes(iteration);
  const uint64_t stored_bytes = table4DBytes(s);
  const bool narrowed = sceneDomain(config).narrowed();
  e.table_4d_bytes = std::max(iteration_bytes, stored_bytes);
  e.density_table_bytes = table4DBytes(densitySizes(iteration));
  const int orders = config.bake.auto_orders ? config.bake.max_orders : config.bake.orders;
  const uint64_t order_radiance =
      product({static_cast<uint64_t>(orderRadianceTablesAtPeak(orders)), table4DBytes(orderRadianceSizes(iteration))});
  // The 4D tables alive at once at the peak of bakeAtmosphere. With one
  // order: the single Rayleigh and Mie tables, the zeroed multiple
  // scattering and density sum. From order 2 on, the larger of two moments:
  // while an order's radiance is integrated (on orderRadianceSizes), the
  // single tables, the density sum, the order's density and its logarithm
  // (baker/stages/multiple_scattering_table.cpp); while the stored multiple
  // scattering is integrated after the loop, the single tables, that table,
  // the density sum and its logarithm.
  auto tablesBytes = [&](int stored, int density, uint64_t radiance) {
    return sum({product({static_cast<uint64_t>(stored), e.table_4d_bytes}),
                product({static_cast<uint64_t>(density), e.density_table_bytes}), radiance});
  };
  if (orders <= 1) {
    e.tables_4d_at_peak = 3;
    e.density_tables_at_peak = 1;
  } else if (tablesBytes(2, 3, order_radiance) >= tablesBytes(3, 2, 0)) {
    e.tables_4d_at_peak = 2;
    e.density_tables_at_peak = 3;
    e.order_radiance_bytes = order_radiance;
  } else {
    e.tables_4d_at_peak = 3;
    e.density_tables_at_peak = 2;
  }
  if (narrowed) e.tables_4d_at_peak += 4;
  // Alive from before order 2 to the end of the order loop; a narrowing
  // scene has a second one on its own texels (its density is computed there).
  auto kernelBytes = [&](const TextureSizes& t) {
    return product({axis(t.scattering_r), axis(t.scattering_mu), kDensityKernelBytesPerRMu});
  };
  e.density_kernel_bytes = orders >= 2 ? sum({kernelBytes(iteration), narrowed ? kernelBytes(densitySizes(s)) : 0}) : 0;
  // 2D: the transmittance table, the summed sky irradiance, and the last
  // order's irradiance beside the one being computed.
  e.peak_bytes = sum({tablesBytes(e.tables_4d_at_peak, e.density_tables_at_peak, e.order_radiance_bytes), transmittance,
                      product({3, irradiance}), e.density_kernel_bytes});
  // The file's tables: single Rayleigh, single Mie, multiple scattering,
  // multiple-scattering density (on densitySizes unless the scene narrows
  // the domain: bakeContents), transmittance and irradiance.
  const uint64_t stored_density_bytes = narrowed ? stored_bytes : table4DBytes(densitySizes(s));
  e.kept_bytes = sum({product({3, stored_bytes}), stored_density_bytes, transmittance, irradiance});
  if (config.atmosphere.storesCieXyz()) {
    // A colour bake runs one pass at a time (the peak above); beside it live
    // the X, Y, Z sums of the file's tables and every wavelength's optical
    // depth in double (baker/bake/colour_bake.cpp).
    const uint64_t depths = product({axis(s.transmittance_mu), axis(s.transmittance_r),
                                     static_cast<uint64_t>(config.atmosphere.wavelengths_nm.size()), sizeof(double)});
    e.peak_bytes = sum({e.peak_bytes, e.kept_bytes, depths});
  }
  if (config.atmosphere.storesLaneGroups() && config.colour_groups.size() > 1) {
    // A spectral bake keeps every pass's tables for the file
    // (baker/bake/spectral_bake.cpp): the earlier passes' beside the one
    // running.
    const uint64_t earlier_passes = config.colour_groups.size() - 1;
    e.peak_bytes = sum({e.peak_bytes, product({earlier_passes, e.kept_bytes})});
    e.kept_bytes = product({static_cast<uint64_t>(config.colour_groups.size()), e.kept_bytes});
  }
  return e;
}

namespace {

// Core-seconds per 4D texel and scattering order of the default Earth bake
// (single scattering, then per order the density and multiple-scattering
// stages, all proportional to the texels): measured on a 2-core AMD EPYC
// (docs/MEASUREMENTS.md, "Job resources").
constexpr double kBakeCoreSecondsPerTexelOrder = 1.2e-6;

}  // namespace

double estimateBakeCoreSeconds(const BakeConfig& config) {
  const TextureSizes iteration = iterationTextureSizes(config);
  const double texels = double(std::max(iteration.scattering_r, 0)) * std::max(iteration.scattering_mu, 0) *
                        std::max(iteration.scattering_mu_s, 0) * std::max(iteration.scattering_nu, 0);
  const int orders = config.bake.auto_orders ? config.bake.max_orders : config.bake.orders;
  // A colour or spectral bake runs the order loop once per pass of
  // kMaxChannels wavelengths.
  const double passes = config.atmosphere.storesCieXyz() || config.atmosphere.storesLaneGroups()
                            ? std::ceil(static_cast<double>(config.atmosphere.wavelengths_nm.size()) / kMaxChannels)
                            : 1.0;
  // Rounded up to a tenth of a second: a time limit, not a measurement.
  return std::ceil(passes * texels * std::max(orders, 1) * kBakeCoreSecondsPerTexelOrder * 10.0) / 10.0;
}

void requireMemoryForBake(const BakeConfig& config, const std::string& source) {
  const BakeMemoryEstimate memory = estimateBakeMemory(config);
  const TextureSizes& s = config.sizes;
  const std::string kernel = memory.density_kernel_bytes > 0 ? fmt::format(" and the scattering density's {} kernel",
                                                                           formatBytes(memory.density_kernel_bytes))
                                                             : "";
  const std::string order_radiance =
      memory.order_radiance_bytes > 0
          ? fmt::format(" and the orders' radiance, {},", formatBytes(memory.order_radiance_bytes))
          : "";
  requireMemoryAvailable(
      fmt::format("{}: resolution.scattering = {} x {} x {} x {}: the bake ({} tables of {}, {} of {}{} "
                  "alive at once{})",
                  source, s.scattering_r, s.scattering_mu, s.scattering_mu_s, s.scattering_nu, memory.tables_4d_at_peak,
                  formatBytes(memory.table_4d_bytes), memory.density_tables_at_peak,
                  formatBytes(memory.density_table_bytes), order_radiance, kernel),
      memory.peak_bytes);
}

}  // namespace skybake
