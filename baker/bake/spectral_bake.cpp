#include "baker/bake/spectral_bake.h"

#include <algorithm>
#include <chrono>

#include "baker/bake/bake_passes.h"
#include "baker/bake/bake_policy.h"
#include "baker/bake/process_usage.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

// Pass `first_channel`..'s lanes of what each order added, into the whole
// bake's per-wavelength figures (0 for orders a pass did not compute).
void addPassOrders(const BakeReport& pass, size_t first_channel, size_t channels, int lanes, BakeReport& report) {
  for (size_t k = 0; k < pass.orders.size(); ++k) {
    if (k == report.wavelength_orders.size()) {
      report.wavelength_orders.push_back(
          {pass.orders[k].order, std::vector<float>(channels, 0.0f), std::vector<float>(channels, 0.0f)});
    }
    for (int l = 0; l < lanes; ++l) {
      report.wavelength_orders[k].mean_radiance[first_channel + l] = pass.orders[k].mean_radiance[l];
      report.wavelength_orders[k].mean_irradiance[first_channel + l] = pass.orders[k].mean_irradiance[l];
    }
  }
  report.wavelength_tail_ratio.resize(channels, 0.0f);
  for (int l = 0; l < lanes; ++l) report.wavelength_tail_ratio[first_channel + l] = pass.tail.ratio[l];
}

}  // namespace

BakeOutput bakeSpectral(const BakeConfig& settled, int threads, ProgressSink& progress) {
  if (!settled.atmosphere.storesLaneGroups() || settled.colour_groups.empty()) {
    throw Error(ErrorKind::Internal, "bakeSpectral: not a settled spectral config");
  }
  const size_t passes = settled.colour_groups.size();
  if (passes == 1) {
    // An ordinary bake of its wavelengths, which is what the file reads back as.
    BakeOutput out = bakeWavelengthPass(passConfig(settled, 0), threads, progress);
    out.report.passes = 1;
    out.file.config_toml = configToToml(settled);
    out.file.report_json = out.report.toJson();
    return out;
  }
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = processCpuSeconds();
  BakeOutput out;
  out.file.contents = bakeContents(settled);
  const size_t channels = settled.atmosphere.wavelengths_nm.size();
  size_t first_channel = 0;
  int orders_computed = 0;
  for (size_t g = 0; g < passes; ++g) {
    const BakeConfig pass_config = passConfig(settled, g);
    PassProgress pass_progress(progress, g, passes);
    BakeOutput pass = bakeWavelengthPass(pass_config, threads, pass_progress);
    out.file.lane_group_tables.push_back(std::move(pass.file.tables));
    addPassRun(pass.report, g, pass_config.atmosphere.wavelengths_nm, out.report);
    const int lanes = pass_config.atmosphere.channelCount();
    addPassOrders(pass.report, first_channel, channels, lanes, out.report);
    orders_computed = std::max(orders_computed, pass.file.orders_computed);
    first_channel += static_cast<size_t>(lanes);
  }
  finishPassesReport(start, cpu_start, out.report);
  out.file.config_toml = configToToml(settled);
  out.file.orders_computed = orders_computed;
  out.file.report_json = out.report.toJson();
  return out;
}

}  // namespace skybake
