// Runs the stress matrix: each case is validated, baked at reduced sizes and
// checked against every table and lookup invariant.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "baker/stress/energy_budget.h"
#include "baker/stress/invariants.h"
#include "baker/stress/stress_cases.h"

namespace skybake {

// The energy budget of a case, with the default quadrature and with every
// node count doubled (the difference shows the quadrature has converged).
struct StressEnergyBudget {
  std::vector<double> wavelengths_nm;  // the channels, in order
  EnergyBudget budget;
  EnergyBudget doubled_quadrature;
};

struct StressRow {
  std::string name;
  std::string description;
  // Non-empty when validateConfig refused the case: the message. A refusal
  // passes only if the message names the key and the reason (see passed()).
  std::string refused;
  int orders_used = 0;
  bool automatic_orders = false;
  bool converged = false;  // automatic orders only
  // Over the single Rayleigh and multiple-scattering tables, W m^-2 nm^-1.
  double scattering_min = 0.0, scattering_max = 0.0;
  double lookup_min = 0.0, lookup_max = 0.0;  // radiance lookups, W m^-2 sr^-1 nm^-1
  long long lookups = 0;
  std::vector<InvariantResult> invariants;
  std::optional<StressEnergyBudget> energy_budget;  // cases with check_energy_budget only
  std::vector<std::string> known_failures;          // from the case: failures that do not fail the run
  std::string known_failure_reason;
  double bake_seconds = 0.0;
  double check_seconds = 0.0;

  bool isKnownFailure(const InvariantResult& invariant) const;
  // Every invariant passed or is a known failure (a refusal: with a clear message).
  bool passed() const;
};

StressRow runStressCase(const StressCase& stress_case, int threads);

// One line per case; invariants that failed are listed under their case with
// the worst offender.
std::string stressTable(const std::vector<StressRow>& rows);
nlohmann::ordered_json stressJson(const std::vector<StressRow>& rows);

}  // namespace skybake
