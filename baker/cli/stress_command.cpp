// skybake stress [--quick] [--json OUT.json] [--case NAME]: bakes the stress
// matrix's extreme atmospheres and checks every invariant (docs/STABILITY.md).
// Exit status 1 when an invariant fails: that is a defect of skybake.
#include <omp.h>

#include <chrono>

#include <fmt/format.h>

#include "baker/cli/commands.h"
#include "baker/cli/option_checks.h"
#include "baker/stages/openmp_threads.h"
#include "baker/stress/stress_matrix.h"
#include "data_formats/atomic_file.h"
#include "data_formats/error.h"

namespace skybake::cli {
namespace {

struct StressOptions {
  bool quick = false;
  std::string json_path;
  std::string case_name;
  int threads = 0;
};

std::vector<StressCase> selectedCases(const StressOptions& o) {
  std::vector<StressCase> cases = stressCases(o.quick);
  if (o.case_name.empty()) return cases;
  std::string names;
  for (StressCase& c : cases) {
    if (c.name == o.case_name) return {std::move(c)};
    names += (names.empty() ? "" : ", ") + c.name;
  }
  throwBadInput(fmt::format("--case = {}: no such stress case (cases: {})", o.case_name, names));
}

void runStress(const StressOptions& o) {
  if (!o.json_path.empty()) requireWritableOutput(o.json_path);
  const std::vector<StressCase> cases = selectedCases(o);
  const ScopedOpenMpThreads thread_count(o.threads);
  const auto start = std::chrono::steady_clock::now();
  std::vector<StressRow> rows;
  for (const StressCase& c : cases) {
    fmt::print(stderr, "stress: {} ...\n", c.name);
    rows.push_back(runStressCase(c, o.threads));
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fmt::print("stress matrix ({}, {} cases, {} threads): every table texel and {} runtime lookups per case\n\n{}",
             o.quick ? "quick" : "full", rows.size(), thread_count.threads(), rows.empty() ? 0 : rows.front().lookups,
             stressTable(rows));
  int failed = 0;
  for (const StressRow& r : rows) failed += r.passed() ? 0 : 1;
  fmt::print("\n{} of {} cases passed in {:.1f} s\n", rows.size() - failed, rows.size(), seconds);

  if (!o.json_path.empty()) {
    nlohmann::ordered_json j = stressJson(rows);
    j["quick"] = o.quick;
    j["threads"] = thread_count.threads();
    j["seconds"] = seconds;
    writeFileContentsAtomically(o.json_path, j.dump(2) + "\n");
  }
  if (failed > 0) {
    throw Error(ErrorKind::Internal, fmt::format("stress: {} of {} cases failed an invariant", failed, rows.size()));
  }
}

}  // namespace

Command addStressCommand(CLI::App& app) {
  auto o = std::make_shared<StressOptions>();
  CLI::App* cmd =
      app.add_subcommand("stress",
                         "Bake extreme atmospheres at reduced sizes and check that tables and lookups stay finite, "
                         "non-negative, bounded and continuous. Exit 1 if any invariant fails.");
  cmd->add_flag("--quick", o->quick, "Smallest tables and a lower order cap (seconds, for CTest).");
  cmd->add_option("--json", o->json_path, "Also write the results as JSON.");
  cmd->add_option("--case", o->case_name, "Run only this case.");
  addThreadsOption(*cmd, o->threads);
  return {cmd, [o] { runStress(*o); }};
}

}  // namespace skybake::cli
