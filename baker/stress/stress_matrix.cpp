#include "baker/stress/stress_matrix.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <initializer_list>
#include <limits>

#include <fmt/format.h>

#include "baker/stress/lookup_invariants.h"
#include "data_formats/error.h"
#include "runtime/sky.h"

namespace skybake {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A refusal is clear when it has the "<source>: <key> = <value>: <reason>"
// shape of every input error.
bool refusalIsClear(const std::string& message) {
  const size_t equals = message.find(" = ");
  return equals != std::string::npos && message.find(": ", equals) != std::string::npos;
}

void tableRange(std::initializer_list<const Texture4D*> tables, int channels, double& lo, double& hi) {
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  for (const Texture4D* table : tables) {
    for (const Spectrum& t : table->texels) {
      for (int c = 0; c < channels; ++c) {
        lo = std::min(lo, double(t[c]));
        hi = std::max(hi, double(t[c]));
      }
    }
  }
}

// Lane c of a spectrum as a share of the power in, for the table.
double shareOfPowerIn(const EnergyBudget& b, const SpectrumD& power, int c) {
  return b.power_in_W_per_nm[c] > 0.0 ? power[c] / b.power_in_W_per_nm[c] : 0.0;
}

// Under the case, one line per channel: where the power goes as shares of
// the power in, the imbalance (with the doubled quadrature beside it) and the
// night side's share beyond the tables' sun range (extrapolated, and at the
// clamped tables' upper bound).
std::string energyBudgetText(const StressEnergyBudget& e) {
  const EnergyBudget& b = e.budget;
  const SpectrumD imbalance = b.relativeImbalance();
  const SpectrumD doubled = e.doubled_quadrature.relativeImbalance();
  std::string text = "    energy budget, shares of the power in: diffuse out + direct out + ground absorbed\n";
  for (size_t c = 0; c < e.wavelengths_nm.size(); ++c) {
    const int i = static_cast<int>(c);
    text += fmt::format(
        "      {:g} nm: {:.4f} + {:.4f} + {:.4f}; imbalance {:+.2f} % (doubled quadrature {:+.2f} %); night side "
        "{:.1e} (clamped {:.1e})\n",
        e.wavelengths_nm[c], shareOfPowerIn(b, b.diffuse_out_W_per_nm, i), shareOfPowerIn(b, b.direct_out_W_per_nm, i),
        shareOfPowerIn(b, b.ground_absorbed_W_per_nm, i), 100.0 * imbalance[i], 100.0 * doubled[i],
        shareOfPowerIn(b, b.diffuse_out_below_domain_W_per_nm, i),
        shareOfPowerIn(b, b.diffuse_out_below_domain_clamped_W_per_nm, i));
  }
  return text;
}

std::string ordersText(const StressRow& row) {
  if (!row.refused.empty()) return "-";
  if (!row.automatic_orders) return fmt::format("{}", row.orders_used);
  return fmt::format("{} auto{}", row.orders_used, row.converged ? "" : " (cap)");
}

}  // namespace

bool StressRow::isKnownFailure(const InvariantResult& invariant) const {
  return std::find(known_failures.begin(), known_failures.end(), invariant.name) != known_failures.end();
}

bool StressRow::passed() const {
  if (!refused.empty()) return refusalIsClear(refused);
  return std::all_of(invariants.begin(), invariants.end(),
                     [&](const InvariantResult& r) { return r.passed() || isKnownFailure(r); });
}

StressRow runStressCase(const StressCase& stress_case, int threads) {
  StressRow row;
  row.name = stress_case.name;
  row.description = stress_case.description;
  row.known_failures = stress_case.known_failures;
  row.known_failure_reason = stress_case.known_failure_reason;
  const BakeConfig& config = stress_case.config;
  try {
    validateConfig(config, stress_case.name);
  } catch (const Error& e) {
    row.refused = e.what();
    return row;
  }

  const auto bake_start = std::chrono::steady_clock::now();
  SilentProgress silent;
  BakeOutput bake = bakeAtmosphere(config, threads, silent);
  row.bake_seconds = secondsSince(bake_start);

  const auto check_start = std::chrono::steady_clock::now();
  const int channels = config.atmosphere.channelCount();
  row.orders_used = bake.file.orders_computed;
  row.automatic_orders = bake.report.orders_decision.automatic;
  row.converged = bake.report.orders_decision.converged;
  tableRange({&bake.file.tables.single_rayleigh, &bake.file.tables.multiple_scattering}, channels, row.scattering_min,
             row.scattering_max);

  const BakeTables& t = bake.file.tables;
  // Optical depth >= 0 is transmittance <= 1; finite is transmittance > 0 or
  // exactly 0 through the ground.
  row.invariants.push_back(checkFiniteNonNegativeTexels("transmittance table (optical depth finite >= 0)",
                                                        t.optical_depth.texels, channels));
  row.invariants.push_back(
      checkFiniteNonNegativeTexels("single_rayleigh table finite >= 0", t.single_rayleigh.texels, channels));
  row.invariants.push_back(checkFiniteNonNegativeTexels("single_mie table finite >= 0", t.single_mie.texels, channels));
  row.invariants.push_back(
      checkFiniteNonNegativeTexels("multiple_scattering table finite >= 0", t.multiple_scattering.texels, channels));
  row.invariants.push_back(checkFiniteNonNegativeTexels("irradiance table finite >= 0", t.irradiance.texels, channels));
  row.invariants.push_back(
      checkFiniteNonNegativeTexels("multiple_density table finite >= 0", t.multiple_density.texels, channels));
  row.invariants.push_back(checkOrdersDecrease(bake.report.orders, channels));

  const Sky sky(std::move(bake.file));
  LookupInvariants lookups = checkLookupInvariants(sky);
  row.lookups = lookups.lookups;
  row.lookup_min = lookups.min_radiance;
  row.lookup_max = lookups.max_radiance;
  for (InvariantResult& r : lookups.invariants) row.invariants.push_back(std::move(r));
  if (stress_case.check_energy_budget) {
    const EnergyBudgetQuadrature quadrature;
    StressEnergyBudget e{config.atmosphere.wavelengths_nm, computeEnergyBudget(sky, quadrature),
                         computeEnergyBudget(sky, quadrature.doubled())};
    row.invariants.push_back(checkEnergyBudget(e.budget, channels, kEnergyBudgetTolerance));
    row.invariants.push_back(checkEnergyBudgetQuadrature(e.budget, e.doubled_quadrature, channels));
    row.energy_budget = std::move(e);
  }
  row.check_seconds = secondsSince(check_start);
  return row;
}

std::string stressTable(const std::vector<StressRow>& rows) {
  std::string text = fmt::format("{:<16} {:>10} {:>21} {:>21} {:>7} {:>7} {}\n", "case", "orders",
                                 "scattering min..max", "lookup min..max", "bake s", "check s", "result");
  for (const StressRow& row : rows) {
    if (!row.refused.empty()) {
      text += fmt::format("{:<16} refused: {} -> {}\n", row.name, row.refused,
                          row.passed() ? "PASS" : "FAIL (unclear message)");
      continue;
    }
    int failed = 0, known = 0;
    for (const InvariantResult& r : row.invariants) {
      if (!r.passed()) (row.isKnownFailure(r) ? known : failed) += 1;
    }
    const std::string result = failed > 0  ? fmt::format("FAIL {}/{}", failed, row.invariants.size())
                               : known > 0 ? "KNOWN FAIL"
                                           : "PASS";
    text += fmt::format("{:<16} {:>10} {:>10.3g}..{:<10.3g} {:>10.3g}..{:<10.3g} {:>7.2f} {:>7.2f} {}\n", row.name,
                        ordersText(row), row.scattering_min, row.scattering_max, row.lookup_min, row.lookup_max,
                        row.bake_seconds, row.check_seconds, result);
    if (row.energy_budget) text += energyBudgetText(*row.energy_budget);
    for (const InvariantResult& r : row.invariants) {
      if (r.passed() && row.isKnownFailure(r)) {
        text += fmt::format("    known failure now passes: {} (remove it from stress_cases.cpp)\n", r.name);
      }
      if (r.passed()) continue;
      text += fmt::format("    {} {}: {} of {} values; worst: {}\n", row.isKnownFailure(r) ? "KNOWN FAIL" : "FAIL",
                          r.name, r.failed, r.checked, r.worst);
      if (row.isKnownFailure(r)) text += fmt::format("      known because: {}\n", row.known_failure_reason);
    }
  }
  return text;
}

namespace {

nlohmann::ordered_json channelsJson(const SpectrumD& values, size_t channels) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (size_t c = 0; c < channels; ++c) out.push_back(values[static_cast<int>(c)]);
  return out;
}

nlohmann::ordered_json energyBudgetJson(const StressEnergyBudget& e) {
  const EnergyBudget& b = e.budget;
  const size_t n = e.wavelengths_nm.size();
  nlohmann::ordered_json j;
  j["wavelengths_nm"] = e.wavelengths_nm;
  j["power_in_W_per_nm"] = channelsJson(b.power_in_W_per_nm, n);
  j["diffuse_out_W_per_nm"] = channelsJson(b.diffuse_out_W_per_nm, n);
  j["diffuse_out_below_domain_W_per_nm"] = channelsJson(b.diffuse_out_below_domain_W_per_nm, n);
  j["diffuse_out_below_domain_clamped_W_per_nm"] = channelsJson(b.diffuse_out_below_domain_clamped_W_per_nm, n);
  j["direct_out_W_per_nm"] = channelsJson(b.direct_out_W_per_nm, n);
  j["ground_absorbed_W_per_nm"] = channelsJson(b.ground_absorbed_W_per_nm, n);
  j["relative_imbalance"] = channelsJson(b.relativeImbalance(), n);
  j["relative_imbalance_doubled_quadrature"] = channelsJson(e.doubled_quadrature.relativeImbalance(), n);
  j["tolerance"] = kEnergyBudgetTolerance;
  j["lookups"] = b.lookups + e.doubled_quadrature.lookups;
  return j;
}

}  // namespace

nlohmann::ordered_json stressJson(const std::vector<StressRow>& rows) {
  nlohmann::ordered_json cases = nlohmann::ordered_json::array();
  for (const StressRow& row : rows) {
    nlohmann::ordered_json c;
    c["case"] = row.name;
    c["description"] = row.description;
    c["passed"] = row.passed();
    if (!row.refused.empty()) {
      c["refused"] = row.refused;
      cases.push_back(c);
      continue;
    }
    c["orders_used"] = row.orders_used;
    c["automatic_orders"] = row.automatic_orders;
    if (row.automatic_orders) c["converged"] = row.converged;
    c["scattering_min"] = row.scattering_min;
    c["scattering_max"] = row.scattering_max;
    c["lookup_radiance_min"] = row.lookup_min;
    c["lookup_radiance_max"] = row.lookup_max;
    c["lookups"] = row.lookups;
    c["bake_seconds"] = row.bake_seconds;
    c["check_seconds"] = row.check_seconds;
    nlohmann::ordered_json invariants = nlohmann::ordered_json::array();
    for (const InvariantResult& r : row.invariants) {
      nlohmann::ordered_json i;
      i["invariant"] = r.name;
      i["passed"] = r.passed();
      if (row.isKnownFailure(r)) i["known_failure"] = row.known_failure_reason;
      i["checked"] = r.checked;
      i["failed"] = r.failed;
      if (!r.passed()) {
        // JSON has no infinity: a NaN/infinite offender is written as null.
        if (std::isfinite(r.worst_excess))
          i["worst_excess"] = r.worst_excess;
        else
          i["worst_excess"] = nullptr;
        i["worst"] = r.worst;
      }
      invariants.push_back(i);
    }
    c["invariants"] = invariants;
    if (row.energy_budget) c["energy_budget"] = energyBudgetJson(*row.energy_budget);
    cases.push_back(c);
  }
  nlohmann::ordered_json out;
  out["all_passed"] = std::all_of(rows.begin(), rows.end(), [](const StressRow& r) { return r.passed(); });
  out["cases"] = cases;
  return out;
}

}  // namespace skybake
