#include <nlohmann/json.hpp>

#include "baker/bake/bake.h"

namespace skybake {

double BakeReport::stageSeconds(const std::string& name) const {
  double total = 0.0;
  for (const StageTiming& t : stages) {
    if (t.stage == name) total += t.seconds;
  }
  return total;
}

std::string BakeReport::toJson(bool with_run_facts) const {
  nlohmann::ordered_json j;
  if (with_run_facts) {
    j["threads"] = threads;
    j["wall_seconds"] = wall_seconds;
    j["cpu_seconds"] = cpu_seconds;
    j["peak_memory_mib"] = peak_memory_mib;
    nlohmann::ordered_json stage_totals = nlohmann::ordered_json::object();
    for (const StageTiming& t : stages) stage_totals[t.stage] = stageSeconds(t.stage);
    j["stage_seconds"] = stage_totals;
    nlohmann::ordered_json per_stage = nlohmann::ordered_json::array();
    for (const StageTiming& t : stages) {
      per_stage.push_back({{"stage", t.stage}, {"order", t.order}, {"seconds", t.seconds}});
    }
    j["stages"] = per_stage;
  }
  nlohmann::ordered_json orders_json = nlohmann::ordered_json::array();
  for (const OrderContribution& o : orders) {
    orders_json.push_back(
        {{"order", o.order},
         {"mean_radiance", {o.mean_radiance[0], o.mean_radiance[1], o.mean_radiance[2], o.mean_radiance[3]}},
         {"mean_irradiance",
          {o.mean_irradiance[0], o.mean_irradiance[1], o.mean_irradiance[2], o.mean_irradiance[3]}}});
  }
  for (const WavelengthOrderContribution& o : wavelength_orders) {
    orders_json.push_back(
        {{"order", o.order}, {"mean_radiance", o.mean_radiance}, {"mean_irradiance", o.mean_irradiance}});
  }
  if (passes > 0) j["passes"] = passes;
  j["orders"] = orders_json;
  const size_t orders_used = wavelength_orders.empty() ? orders.size() : wavelength_orders.size();
  nlohmann::ordered_json decision = {{"orders_used", static_cast<int>(orders_used)},
                                     {"mode", orders_decision.automatic ? "auto" : "fixed"},
                                     {"last_order_share", orders_decision.last_order_share},
                                     {"worst_slice_altitude_m", orders_decision.worst_altitude_m},
                                     {"worst_slice_sun_zenith_deg", orders_decision.worst_sun_zenith_deg},
                                     {"mean_last_order_share", orders_decision.mean_last_order_share}};
  if (orders_decision.automatic) {
    decision["tolerance"] = orders_decision.tolerance;
    decision["max_orders"] = orders_decision.cap;
    decision["converged"] = orders_decision.converged;
  }
  j["orders_decision"] = decision;
  const nlohmann::ordered_json ratio =
      wavelength_tail_ratio.empty() ? nlohmann::ordered_json{tail.ratio[0], tail.ratio[1], tail.ratio[2], tail.ratio[3]}
                                    : nlohmann::ordered_json(wavelength_tail_ratio);
  j["tail_estimate"] = {{"applied", tail.applied}, {"ratio", ratio}, {"reason", tail.reason}};
  return j.dump(2);
}

void setStoredReport(BakeOutput& bake, bool with_run_facts) {
  bake.file.report_json = bake.report.toJson(with_run_facts);
}

}  // namespace skybake
