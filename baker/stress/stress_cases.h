// The stress matrix's atmospheres: extreme but physically meaningful configs
// (thick haze, a Venus-like sky, no atmosphere, extreme phase functions and
// planet sizes, ...) baked at reduced sizes to check that every table and
// lookup stays finite, non-negative and continuous (docs/STABILITY.md).
#pragma once

#include <string>
#include <vector>

#include "data_formats/config/config.h"

namespace skybake {

struct StressCase {
  std::string name;         // short identifier, used by `skybake stress --case`
  std::string description;  // what is extreme about it
  BakeConfig config;
  // Invariants this case is known to break (InvariantResult::name) and why: a
  // defect found by the matrix and not yet fixed. They are still checked and
  // shown as KNOWN FAIL, but do not fail the run; one that starts to pass is
  // reported so the entry can be removed.
  std::vector<std::string> known_failures;
  std::string known_failure_reason;
  // Check the energy budget (baker/stress/energy_budget.h): only meaningful
  // where nothing absorbs in the air, so that what comes in must leave or be
  // absorbed by the ground.
  bool check_energy_budget = false;
};

// quick: the sizes of a unit-test bake (a few seconds for the whole matrix);
// otherwise somewhat larger tables and a higher order cap.
std::vector<StressCase> stressCases(bool quick);

// Mars as shipped in data_formats/presets/mars.toml (compiled in).
BakeConfig builtinMarsConfig();

}  // namespace skybake
