#include "baker/bake/bake_passes.h"

#include <algorithm>

#include <fmt/format.h>

#include "baker/bake/process_usage.h"

namespace skybake {

BakeConfig passConfig(const BakeConfig& settled, size_t g) {
  BakeConfig pass = settled;
  pass.atmosphere = settled.colour_groups.at(g);
  pass.colour_groups.clear();
  return pass;
}

void PassProgress::beginStage(const std::string& name, size_t work_units) {
  inner_.beginStage(fmt::format("pass {}/{}: {}", pass_ + 1, passes_, name), work_units);
}

void addPassRun(const BakeReport& pass, size_t index, const std::vector<double>& pass_wavelengths_nm,
                BakeReport& report) {
  for (const StageTiming& t : pass.stages) {
    auto same = [&](const StageTiming& r) { return r.stage == t.stage && r.order == t.order; };
    const auto found = std::find_if(report.stages.begin(), report.stages.end(), same);
    if (found == report.stages.end()) {
      report.stages.push_back(t);
    } else {
      found->seconds += t.seconds;
    }
  }
  OrdersDecision& d = report.orders_decision;
  d.automatic = pass.orders_decision.automatic;
  d.tolerance = pass.orders_decision.tolerance;
  d.cap = pass.orders_decision.cap;
  d.converged = (index == 0 || d.converged) && pass.orders_decision.converged;
  if (index == 0 || pass.orders_decision.last_order_share > d.last_order_share) {
    d.last_order_share = pass.orders_decision.last_order_share;
    d.worst_altitude_m = pass.orders_decision.worst_altitude_m;
    d.worst_sun_zenith_deg = pass.orders_decision.worst_sun_zenith_deg;
  }
  d.mean_last_order_share = std::max(d.mean_last_order_share, pass.orders_decision.mean_last_order_share);
  report.tail.applied = (index == 0 || report.tail.applied) && pass.tail.applied;
  std::string wavelengths;
  for (double nm : pass_wavelengths_nm) wavelengths += fmt::format("{}{}", wavelengths.empty() ? "" : " ", nm);
  report.tail.reason +=
      fmt::format("{}pass {} ({} nm): {}", index == 0 ? "" : "; ", index + 1, wavelengths, pass.tail.reason);
  report.threads = pass.threads;
  report.passes = static_cast<int>(index) + 1;
}

void finishPassesReport(std::chrono::steady_clock::time_point start, double cpu_start, BakeReport& report) {
  report.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.cpu_seconds = processCpuSeconds() - cpu_start;
  report.peak_memory_mib = peakMemoryMiB();
}

}  // namespace skybake
