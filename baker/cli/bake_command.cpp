// skybake bake [CONFIG.toml] -o OUT.exr [--orders N] [--threads N] [--precision half|float] [--outputs ...]
//   [--altitude-range LOW:HIGH] [--sun-zenith-range LOW:HIGH] [--sky-views-only] [--target-error PERCENT]
//   [--combined-single-mie]
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "baker/bake/bake.h"
#include "baker/bake/bake_policy.h"
#include "baker/bake/process_usage.h"
#include "baker/bake/table_memory.h"
#include "baker/cli/available_memory.h"
#include "baker/cli/bake_memory_estimate.h"
#include "baker/cli/commands.h"
#include "baker/cli/option_checks.h"
#include "baker/cli/report_sidecar.h"
#include "baker/cli/scene_size_report.h"
#include "baker/cli/size_choice.h"
#include "baker/cli/target_error_check.h"
#include "baker/cli/terminal_progress.h"
#include "baker/validation/validation.h"
#include "data_formats/atomic_file.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"
#include "data_formats/parameterization/texture_mapping.h"
#include "data_formats/terminal_text.h"

namespace skybake::cli {
namespace {

struct BakeOptions {
  std::string config_path;  // empty: the built-in Earth
  std::string output_path;
  std::string orders;                       // empty: from the config; "auto" or a count
  std::optional<double> order_tolerance;    // absent: from the config
  int threads = 0;                          // 0: all cores (OpenMP's default)
  std::string precision;                    // empty: from the config
  std::vector<std::string> outputs;         // empty: from the config
  std::string altitude_range;               // "LOW:HIGH" metres; empty: from the config
  std::string sun_zenith_range;             // "LOW:HIGH" degrees; empty: from the config
  std::optional<std::string> target_error;  // "0.5%" or "0.5"; absent: the config's sizes
  std::optional<int> reference_samples;     // the --target-error check's paths per query; absent: validate's default
  std::string max_file_size;                // "8MiB", "5e6"; empty: no budget
  bool reproducible = false;
  bool combined_single_mie = false;  // false: from the config
  bool sky_views_only = false;       // false: from the config
  bool estimate = false;             // print the resources the bake needs, bake nothing
};

// What a bake of `config` needs, as JSON for job schedulers (a cluster
// profile's memory and time requests): peak table memory and the
// core-seconds estimate (bake_memory_estimate.h).
void printBakeEstimate(const BakeConfig& config, const std::string& source) {
  const BakeMemoryEstimate memory = estimateBakeMemory(config);
  const TextureSizes& s = config.sizes;
  const nlohmann::ordered_json j{
      {"source", source},
      {"scattering_size", {s.scattering_r, s.scattering_mu, s.scattering_mu_s, s.scattering_nu}},
      {"orders_at_most", config.bake.auto_orders ? config.bake.max_orders : config.bake.orders},
      {"peak_table_bytes", memory.peak_bytes},
      {"file_table_bytes", memory.kept_bytes},
      {"estimated_core_seconds", estimateBakeCoreSeconds(config)}};
  fmt::print("{}\n", j.dump(2));
}

std::string stageSummary(const BakeReport& report) {
  std::string text;
  for (const char* stage : {"transmittance", "direct_irradiance", "single_scattering", "scattering_density",
                            "indirect_irradiance", "order_radiance", "multiple_scattering"}) {
    text += fmt::format("{}{} {:.2f} s", text.empty() ? "" : ", ", stage, report.stageSeconds(stage));
  }
  if (const double scene = report.stageSeconds("scene_tables"); scene > 0.0) {
    text += fmt::format(", scene_tables {:.2f} s", scene);
  }
  return text;
}

// --target-error's percentage; refuses what is not one.
double targetPercent(const std::string& text) {
  const std::string number = !text.empty() && text.back() == '%' ? text.substr(0, text.size() - 1) : text;
  char* end = nullptr;
  const double percent = std::strtod(number.c_str(), &end);
  if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(percent) || percent <= 0.0 ||
      percent >= 100.0) {
    refuseOptionValue("--target-error", text, "must be a percentage in (0, 100), such as 0.5% or 0.5");
  }
  return percent;
}

// --max-file-size in bytes: a number with an optional B, KB, MB, GB (powers
// of 1000) or KiB, MiB, GiB (of 1024); refuses anything else.
uintmax_t fileSizeBudget(const std::string& text) {
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  std::string unit(end);
  unit.erase(0, unit.find_first_not_of(' '));
  const std::pair<const char*, double> units[] = {{"", 1.0},          {"B", 1.0},           {"KB", 1e3},
                                                  {"MB", 1e6},        {"GB", 1e9},          {"KiB", 1024.0},
                                                  {"MiB", 1048576.0}, {"GiB", 1073741824.0}};
  for (const auto& [name, factor] : units) {
    const double bytes = number * factor;
    if (unit == name && end != text.c_str() && std::isfinite(bytes) && bytes >= 1.0 && bytes < 1e18) {
      return static_cast<uintmax_t>(bytes);
    }
  }
  refuseOptionValue("--max-file-size", text, "must be a size such as 8MiB, 20MB or 5000000 (bytes)");
}

// Refuses a target the sweep cannot meet or that is not a percentage.
SizeChoice sizesForTargetError(const std::string& text) {
  const std::optional<SizeChoice> choice = chooseSizesForError(targetPercent(text));
  if (!choice) {
    const SweepPoint& best = earthSweep().back();
    refuseOptionValue("--target-error", text,
                      fmt::format("below what the sweep reached ({:g} % at {:g}x the default sizes, "
                                  "docs/ERROR_VS_TIME.md); set resolution.scattering yourself and validate",
                                  worstPercent(best), best.scale));
  }
  return *choice;
}

void runBake(const BakeOptions& o) {
  BakeConfig config = o.config_path.empty() ? builtinEarthConfig() : loadConfigFile(o.config_path);
  const std::string source = o.config_path.empty() ? "<built-in earth>" : o.config_path;
  if (!o.orders.empty()) applyOrdersChoice("--orders", o.orders, config);
  if (o.order_tolerance) config.bake.order_tolerance = *o.order_tolerance;
  if (o.precision == "half") config.bake.precision = StoragePrecision::Half;
  if (o.precision == "float") config.bake.precision = StoragePrecision::Float;
  if (o.combined_single_mie) config.bake.combined_single_mie = true;
  if (!o.outputs.empty()) {
    if (std::find(o.outputs.begin(), o.outputs.end(), "sky_radiance") == o.outputs.end()) {
      refuseOptionValue("--outputs", fmt::format("{}", fmt::join(o.outputs, ",")),
                        "must include sky_radiance: the other outputs are built on its tables");
    }
    config.scene.radiance_to_points =
        std::find(o.outputs.begin(), o.outputs.end(), "radiance_to_points") != o.outputs.end();
    config.scene.ground_irradiance =
        std::find(o.outputs.begin(), o.outputs.end(), "ground_irradiance") != o.outputs.end();
  }
  if (!o.altitude_range.empty()) {
    config.scene_ranges.altitude_m = parseRangeOption("--altitude-range", o.altitude_range);
  }
  if (!o.sun_zenith_range.empty()) {
    config.scene_ranges.sun_zenith_deg = parseRangeOption("--sun-zenith-range", o.sun_zenith_range);
  }
  if (o.sky_views_only) config.scene_ranges.views_below_horizon = false;
  const std::optional<uintmax_t> budget_bytes =
      o.max_file_size.empty() ? std::nullopt : std::optional<uintmax_t>(fileSizeBudget(o.max_file_size));
  if (budget_bytes && o.target_error) {
    refuseOptionValue("--max-file-size", o.max_file_size,
                      "cannot be combined with --target-error (each chooses the sizes): give one");
  }
  if (budget_bytes && o.estimate) {
    refuseOptionValue("--max-file-size", o.max_file_size,
                      "cannot be combined with --estimate: the sizes that fit are known only once baked");
  }
  if (o.reference_samples && !o.target_error) {
    refuseOptionValue("--reference-samples", std::to_string(*o.reference_samples),
                      "sets the paths of --target-error's check: give --target-error too");
  }
  // The config as asked for; --target-error then gives it the whole
  // domain's sizes (a scene's are chosen from them).
  const BakeConfig requested = config;
  auto withSizes = [&](const SizeChoice& choice) {
    BakeConfig sized = requested;
    sized.sizes = choice.sizes;
    sized.sizes.scene = requested.sizes.scene;
    sized.sizes.iteration = requested.sizes.iteration;
    return sized;
  };
  std::optional<SizeChoice> size_choice;
  if (o.target_error) {
    size_choice = sizesForTargetError(*o.target_error);
    config = withSizes(*size_choice);
  }
  validateConfig(config, source + " (with command-line overrides)");
  const BakeConfig settled = settledBakeConfig(config);
  std::optional<SceneSizeChoice> scene_sizes = sceneSizeChoice(config, settled);
  if (config.scene_ranges.sun_zenith_deg && !settled.scene_ranges.sun_zenith_deg) {
    const std::array<double, 2>& range = *config.scene_ranges.sun_zenith_deg;
    fmt::print(stderr,
               "skybake: scene.sun_zenith_range_deg {:g}:{:g} covers all but less than a texel of the sun axis "
               "(0 to {:g} deg): the tables keep the whole axis\n",
               range[0], range[1], config.atmosphere.sun_max_zenith_deg);
  }
  config = settled;
  if (o.estimate) {
    printBakeEstimate(config, source);
    return;
  }
  if (o.output_path.empty()) throwBadInput("bake: -o,--output is required (unless --estimate)");

  const std::filesystem::path output(o.output_path);
  // Neither output may replace the config or a spectrum file it names.
  requireWritableOutput(output, config.input_files);
  requireWritableOutput(reportSidecarPath(output), config.input_files);
  requireMemoryForBake(config, source);

  if (scene_sizes) fmt::print(stderr, "skybake: {}\n", scene_sizes->description);
  auto printSizeChoice = [&] {
    const TextureSizes& c = size_choice->sizes;
    fmt::print(stderr,
               "skybake: --target-error {}: {:g}x the default sizes (scattering {} x {} x {} x {}), where the sweep of "
               "the built-in Earth measured {:.2f} % sky radiance RMS (worst channel, day and low sun) and {:.1f} s on "
               "2 threads (docs/ERROR_VS_TIME.md); checked on this bake afterwards\n",
               *o.target_error, size_choice->scale, c.scattering_r, c.scattering_mu, c.scattering_mu_s, c.scattering_nu,
               size_choice->predicted_percent, size_choice->predicted_bake_seconds);
  };
  if (size_choice) printSizeChoice();
  keepFreedTableMemory();
  TerminalProgress progress;
  BakeOutput bake = bakeAtmosphere(config, o.threads, progress);
  // Bakes again at a size of the sweep (--target-error, --max-file-size).
  auto bakeAgainAt = [&](const SizeChoice& choice) {
    const BakeConfig sized = withSizes(choice);
    validateConfig(sized, source + " (with command-line overrides)");
    config = settledBakeConfig(sized);
    scene_sizes = sceneSizeChoice(sized, config);
    requireMemoryForBake(config, source);
    if (scene_sizes) fmt::print(stderr, "skybake: {}\n", scene_sizes->description);
    bake = BakeOutput();  // its tables freed before the next bake's
    bake = bakeAtmosphere(config, o.threads, progress);
  };
  // --target-error: the bake's own day sky error on the quick query set,
  // and the sweep's next size while it misses the target.
  std::optional<TargetErrorCheck> target_check;
  if (size_choice) {
    const double target = targetPercent(*o.target_error);
    for (;;) {
      target_check = checkTargetError(bake.file, o.reference_samples.value_or(ReferenceSettings{}.paths), progress);
      if (!target_check->checked || target_check->meets(target)) break;
      const std::optional<SizeChoice> next = nextLargerSweptSizes(size_choice->scale);
      if (!next) break;
      fmt::print(stderr, "skybake: --target-error {}: {:.2f} % by day at {:g}x the default sizes; trying {:g}x\n",
                 *o.target_error, target_check->day_percent, size_choice->scale, next->scale);
      size_choice = next;
      printSizeChoice();
      bakeAgainAt(*size_choice);
    }
    const TargetErrorCheck& c = *target_check;
    if (!c.checked) {
      fmt::print(stderr, "skybake: --target-error {}: not checked: {}\n", *o.target_error, c.reason);
    } else {
      fmt::print(stderr,
                 "skybake: --target-error {}: {} at {:g}x the default sizes: day sky radiance {:.2f} % RMS (worst "
                 "channel, {} queries of the quick set, the reference's noise {:.2f} %), low sun {:.2f} %{}\n",
                 *o.target_error,
                 c.meets(target) ? "met" : fmt::format("NOT met, {:.2f} points over, even", c.day_percent - target),
                 size_choice->scale, c.day_percent, c.queries, c.reference_noise_percent, c.low_sun_percent,
                 c.meets(target) ? "" : "; set resolution.scattering yourself and validate (docs/LEAVE_OUT.md)");
    }
  }
  // --max-file-size: the config's sizes, then the sweep's smaller ones, until
  // the written file fits (it is measured as the temporary file, so that an
  // existing bake is replaced only by one that fits).
  std::optional<SizeChoice> budget_choice;
  auto nextSmallerForBudget = [&]() -> std::optional<SizeChoice> {
    const std::vector<SweepPoint>& sweep = earthSweep();
    for (auto p = sweep.rbegin(); p != sweep.rend(); ++p) {
      const SizeChoice c = sizeChoiceAt(*p);
      if (settledBakeConfig(withSizes(c)).sizes.scatteringTexels() < config.sizes.scatteringTexels()) return c;
    }
    return std::nullopt;
  };
  uintmax_t bytes = 0;
  auto writeSidecar = [&](const std::filesystem::path&) {
    const nlohmann::ordered_json report = nlohmann::ordered_json::parse(bake.report.toJson(!o.reproducible));
    nlohmann::ordered_json sidecar{{"bake_file", o.output_path},
                                   {"atmosphere", config.name},
                                   {"file_size_bytes", bytes},
                                   {"orders", bake.file.orders_computed},
                                   // The whole process so far, start-up and the file's write
                                   // included: what the user waited for (the report's own
                                   // wall_seconds are the stages').
                                   {"process_wall_seconds", processWallSeconds()},
                                   {"bake", report}};
    if (size_choice) {
      sidecar["size_choice"] = {{"target_error_percent", *o.target_error},
                                {"scale_of_default_sizes", size_choice->scale},
                                {"predicted_error_percent", size_choice->predicted_percent},
                                {"predicted_bake_seconds_2_threads", size_choice->predicted_bake_seconds},
                                {"model",
                                 "sky radiance RMS, worst channel of the day and low-sun bands, "
                                 "as measured in the sweep of the built-in Earth "
                                 "(docs/ERROR_VS_TIME.md)"},
                                {"met", target_check->meets(targetPercent(*o.target_error))},
                                {"check", target_check->toJson()}};
    }
    if (scene_sizes) sidecar["scene_sizes"] = scene_sizes->json;
    if (budget_bytes) {
      sidecar["file_size_budget"] = {
          {"max_file_size", o.max_file_size},
          {"max_bytes", *budget_bytes},
          {"scale_of_default_sizes", budget_choice ? budget_choice->scale : 0.0},
          {"sizes", budget_choice ? "a size of the sweep of the built-in Earth" : "the config's"}};
    }
    writeReportSidecar(output, sidecar);
  };
  bool over_budget = false;
  for (;;) {
    setStoredReport(bake, !o.reproducible);
    // The sidecar is written while the new bake is still a temporary file: if
    // it cannot be, the existing bake stays in place with its own report.
    setBakeFileWriteThreads(bake.report.threads);
    try {
      writeBakeFile(output, bake.file, [&](const std::filesystem::path& temp) {
        bytes = std::filesystem::file_size(temp);
        if (budget_bytes && bytes > *budget_bytes) {
          over_budget = true;
          throw Error(ErrorKind::BadInput, "over the file size budget");
        }
        writeSidecar(temp);
      });
      break;
    } catch (const Error&) {
      if (!over_budget) throw;
    }
    over_budget = false;
    const std::optional<SizeChoice> smaller = nextSmallerForBudget();
    if (!smaller) {
      refuseOptionValue(
          "--max-file-size", o.max_file_size,
          fmt::format("at {} the file is {:.2f} MiB ({} bytes), and the sweep offers no smaller size; set "
                      "resolution.scattering yourself",
                      budget_choice ? fmt::format("{:g}x the default sizes", budget_choice->scale)
                                    : std::string("the config's sizes"),
                      bytes / 1048576.0, bytes));
    }
    fmt::print(stderr, "skybake: --max-file-size {}: {:.2f} MiB at these sizes; trying {:g}x the default sizes\n",
               o.max_file_size, bytes / 1048576.0, smaller->scale);
    budget_choice = smaller;
    bakeAgainAt(*budget_choice);
  }
  if (budget_bytes) {
    fmt::print(stderr, "skybake: --max-file-size {}: {:.2f} MiB ({} bytes) at {}\n", o.max_file_size, bytes / 1048576.0,
               bytes,
               budget_choice ? fmt::format("{:g}x the default sizes", budget_choice->scale) : "the config's sizes");
  }
  const OrdersDecision& decision = bake.report.orders_decision;
  // Where the last order still adds most (the slowest-converging altitude
  // and sun): what the orders leave out, said for every bake.
  const std::string worst_slice =
      fmt::format("the last adds {:.2g} of the light at {:.0f} m, sun zenith {:.1f} deg", decision.last_order_share,
                  decision.worst_altitude_m, decision.worst_sun_zenith_deg);
  const std::string orders_note =
      !decision.automatic  ? "; " + worst_slice
      : decision.converged ? ", automatic; " + worst_slice
                           : fmt::format(", automatic, NOT converged at the cap of {}; {}", decision.cap, worst_slice);
  fmt::print(stderr,
             "skybake: baked '{}' ({} orders{}) into {} ({:.1f} MiB) in {:.2f} s on {} threads ({:.2f} s in the "
             "stages: {})\n",
             terminalSafe(config.name), bake.file.orders_computed, orders_note, o.output_path,
             bytes / (1024.0 * 1024.0), processWallSeconds(), bake.report.threads, bake.report.wall_seconds,
             stageSummary(bake.report));
}

}  // namespace

Command addBakeCommand(CLI::App& app) {
  auto options = std::make_shared<BakeOptions>();
  CLI::App* cmd = app.add_subcommand("bake", "Bake an atmosphere into one OpenEXR file.");
  cmd->add_option("config", options->config_path,
                  "Atmosphere config (TOML, see data_formats/CONFIG.md). Without it, the built-in "
                  "Earth (data_formats/presets/earth.toml).");
  cmd->add_option("-o,--output", options->output_path, "Output bake file (.exr); required unless --estimate.");
  cmd->add_option("--orders", options->orders,
                  "Scattering orders to compute, or 'auto' to iterate until the last order adds less than "
                  "bake.order_tolerance of the total (overrides bake.orders).")
      ->check(CLI::Validator(
          [](std::string& value) -> std::string {
            requireOrdersChoice("--orders", value);
            return "";
          },
          fmt::format("auto|1..{}", kMaxOrders)));
  requireFiniteIn(cmd->add_option("--order-tolerance", options->order_tolerance,
                                  "With automatic orders: stop when the last order adds less than this share "
                                  "of the total (overrides bake.order_tolerance)."),
                  kMinOrderTolerance, kMaxOrderTolerance);
  addThreadsOption(*cmd, options->threads);
  cmd->add_option(
         "--precision", options->precision,
         "Storage of the 4D tables in the file (overrides bake.precision; default half, scaled per (r, mu_s) slice).")
      ->check(CLI::IsMember({"half", "float"}));
  cmd->add_option("--outputs", options->outputs,
                  "What the scene uses, comma separated: sky_radiance (always), radiance_to_points, "
                  "ground_irradiance; the tables of the others are left out of the file (overrides "
                  "scene.outputs).")
      ->delimiter(',')
      ->check(CLI::IsMember({"sky_radiance", "radiance_to_points", "ground_irradiance"}));
  cmd->add_option("--altitude-range", options->altitude_range,
                  "LOW:HIGH, metres above the ground: the altitudes of the scene's cameras and of the points "
                  "they look at; the 4D tables cover only these, widened to the whole axis's next texels, and the bake "
                  "chooses their sizes (docs/LEAVE_OUT.md; overrides scene.altitude_range_m).");
  cmd->add_option("--sun-zenith-range", options->sun_zenith_range,
                  "LOW:HIGH, degrees: the scene's sun zenith angles; the 4D tables cover only these, plus "
                  "1 deg each side, on the whole axis's own texels (overrides scene.sun_zenith_range_deg).");
  cmd->add_flag("--sky-views-only", options->sky_views_only,
                "The scene's views never look below the horizon (sets scene.views_below_horizon = false): the 4D "
                "tables hold only rays that reach the sky, on half the view texels (half the file); lookups of rays "
                "toward the ground "
                "integrate along the ray instead, about 20 times slower (docs/LEAVE_OUT.md).");
  cmd->add_option("--target-error", options->target_error,
                  "A sky radiance error to aim for, e.g. 1%: every table size becomes the smallest multiple of "
                  "the default sizes measured in the sweep of the built-in Earth (0.5x, 0.75x, 1x) whose error "
                  "(docs/ERROR_VS_TIME.md) meets it. The bake is then checked against the reference on the quick "
                  "query set's day sky (about a minute the first time for an atmosphere, cached after) and baked "
                  "at the sweep's next size while it misses; the result, met or by how much not, is printed and "
                  "written to the report. Overrides the config's [resolution] sizes (a scene's are chosen from "
                  "them).");
  requireWholeIn(cmd->add_option("--reference-samples", options->reference_samples,
                                 "With --target-error: Monte Carlo paths per reference query of its check (default "
                                 "32768, as skybake validate; fewer check faster and more noisily)."),
                 1, kMaxReferencePaths);
  cmd->add_option("--max-file-size", options->max_file_size,
                  "A budget for the bake file, e.g. 8MiB, 20MB or 5000000 (bytes): the config's sizes, then the "
                  "smaller sizes of the sweep of the built-in Earth (0.75x, 0.5x the defaults; a scene's chosen "
                  "from them), until the written file fits; the size used is printed and written to the report. "
                  "Not with --target-error.");
  cmd->add_flag("--combined-single-mie", options->combined_single_mie,
                "Store single Mie scattering as one channel beside single Rayleigh scattering and rebuild the "
                "others from the Rayleigh channels (sets bake.combined_single_mie): a smaller file, less "
                "accurate near the sun (docs/LEAVE_OUT.md).");
  cmd->add_flag("--estimate", options->estimate,
                "Print (JSON) the peak table memory and the estimated core-seconds of this bake, with every other "
                "option applied, and bake nothing.");
  cmd->add_flag("--reproducible", options->reproducible,
                "Leave times, thread count and memory out of the file header, so the same config "
                "always gives a byte-identical file.");
  return {cmd, [options] { runBake(*options); }};
}

}  // namespace skybake::cli
