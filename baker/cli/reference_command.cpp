// skybake reference [CONFIG.toml|BAKE.exr] [--queries SET] [--piece K/N] [--estimate]
//
// Computes the reference for an atmosphere's query set into the reference
// cache, whole or one piece of it, so that a sweep's validate jobs (or a
// cluster's) find it there instead of each computing the same reference.
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "baker/cli/commands.h"
#include "baker/cli/option_checks.h"
#include "baker/cli/reference_options.h"
#include "baker/cli/terminal_progress.h"
#include "baker/cli/wavelength_channels.h"
#include "baker/stages/openmp_threads.h"
#include "baker/validation/validation.h"
#include "data_formats/config/config.h"
#include "runtime/sky.h"

namespace skybake::cli {
namespace {

// Core-seconds one Monte Carlo path of a reference query takes, averaged over
// the standard query set (its twilight and space queries cost more than its
// day queries): measured on a 2-core AMD EPYC (docs/MEASUREMENTS.md,
// "Job resources"). --estimate multiplies it by paths and queries; a
// cluster profile adds its own margin for slower or busier nodes.
constexpr double kReferenceCoreSecondsPerPath = 2.1e-5;

// More pieces than this would be more jobs than queries in any shipped set.
constexpr long long kMaxReferencePieces = 100000;

struct ReferenceOptions {
  std::string source_path;  // config (.toml) or bake (.exr); empty: the built-in Earth
  std::string queries = "standard";
  int reference_samples = ReferenceSettings{}.paths;
  std::string piece;  // "K/N"; empty: the whole set
  std::string cache_dir;
  bool estimate = false;
  int threads = 0;
};

struct Piece {
  int index = 1, count = 1;
};

Piece parsePiece(const std::string& text) {
  if (text.empty()) return {};
  const size_t slash = text.find('/');
  const auto k = slash == std::string::npos ? std::nullopt : parseWholeNumber(text.substr(0, slash));
  const auto n = slash == std::string::npos ? std::nullopt : parseWholeNumber(text.substr(slash + 1));
  if (!k || !n || *n < 1 || *n > kMaxReferencePieces || *k < 1 || *k > *n) {
    refuseOptionValue("--piece", text,
                      fmt::format("must be K/N, whole numbers with 1 <= K <= N <= {}", kMaxReferencePieces));
  }
  return {static_cast<int>(*k), static_cast<int>(*n)};
}

// The atmospheres whose references the source needs: its own, or a
// spectral bake's or config's lane groups (each a reference of its own, in
// its own cache directory, as validate computes them).
std::vector<AtmosphereParameters> referenceAtmospheresOf(const std::string& path) {
  if (path.empty()) return {builtinEarthConfig().atmosphere};
  AtmosphereParameters a;
  std::vector<AtmosphereParameters> lane_groups;
  if (std::filesystem::path(path).extension() == ".exr") {
    const Sky sky = Sky::load(path);
    a = sky.atmosphere();
    lane_groups = sky.contents().lane_groups;
  } else {
    const BakeConfig config = loadConfigFile(path);
    a = config.atmosphere;
    if (a.storesLaneGroups()) lane_groups = config.colour_groups;
  }
  requireWavelengthChannels(a, path, "reference");
  if (!a.storesLaneGroups()) return {a};
  return lane_groups;
}

std::string wavelengthList(const AtmosphereParameters& a) {
  std::string out;
  for (double nm : a.wavelengths_nm) out += fmt::format("{}{}", out.empty() ? "" : " ", nm);
  return out;
}

void runReference(const ReferenceOptions& o) {
  const ScopedOpenMpThreads thread_count(o.threads);
  const Piece piece = parsePiece(o.piece);
  const std::vector<AtmosphereParameters> groups = referenceAtmospheresOf(o.source_path);
  const AtmosphereParameters& a = groups.front();
  const QuerySet queries =
      queryPiece(querySetNamed(o.queries, a.bottom_radius_m, a.top_radius_m), piece.index, piece.count);
  const ReferenceSettings settings = referenceSettings(o.reference_samples, o.cache_dir, false);
  const std::string source = o.source_path.empty() ? "<built-in earth>" : o.source_path;
  const size_t total = queries.radiance.size() + queries.irradiance.size();
  if (o.estimate) {
    size_t missing = 0;
    double missing_paths = 0.0;
    nlohmann::ordered_json lane_groups = nlohmann::ordered_json::array();
    std::string directory;
    for (const AtmosphereParameters& group : groups) {
      const ReferenceCache cache(settings.cache_directory, group, settings.paths);
      const std::vector<size_t> group_items = queriesMissingFromCache(cache, queries);
      const size_t group_missing = group_items.size();
      for (size_t item : group_items) missing_paths += referencePathsFor(queries, item, settings.paths);
      missing += group_missing;
      directory = cache.directory().string();
      lane_groups.push_back({{"wavelengths_nm", group.wavelengths_nm},
                             {"cached", total - group_missing},
                             {"to_compute", group_missing},
                             {"cache_directory", directory}});
    }
    // Counted over every lane group's reference: a spectral source's queries are computed once per group.
    nlohmann::ordered_json j{{"source", source},
                             {"query_set", queries.name},
                             {"piece", fmt::format("{}/{}", piece.index, piece.count)},
                             {"paths_per_query", settings.paths},
                             {"queries", total * groups.size()},
                             {"cached", total * groups.size() - missing},
                             {"to_compute", missing},
                             {"estimated_core_seconds", std::ceil(missing_paths * kReferenceCoreSecondsPerPath)}};
    if (groups.size() == 1) {
      j["cache_directory"] = directory;
    } else {
      j["lane_groups"] = lane_groups;
    }
    fmt::print("{}\n", j.dump(2));
    return;
  }
  TerminalProgress progress;
  for (size_t g = 0; g < groups.size(); ++g) {
    const std::string stage =
        groups.size() == 1 ? "reference" : fmt::format("reference, lane group {}/{}", g + 1, groups.size());
    const ReferenceValues reference = computeReferenceValues(groups[g], queries, settings, progress, stage);
    fmt::print(
        "reference for {}{} ({} paths per query, {} times that for rays to points with the sun below the "
        "horizon), query set '{}' piece {} of {}: {} radiance and {} irradiance queries ({} from the cache, {} "
        "computed in {:.1f} s) in {}\n",
        source,
        groups.size() == 1
            ? ""
            : fmt::format(", lane group {} of {} ({} nm)", g + 1, groups.size(), wavelengthList(groups[g])),
        settings.paths, kTwilightPointRayPathFactor, queries.name, piece.index, piece.count, queries.radiance.size(),
        queries.irradiance.size(), reference.cached, reference.computed, reference.seconds,
        settings.cache_directory.string());
  }
}

}  // namespace

Command addReferenceCommand(CLI::App& app) {
  auto o = std::make_shared<ReferenceOptions>();
  CLI::App* cmd = app.add_subcommand(
      "reference",
      "Compute an atmosphere's reference values into the reference cache (whole or one piece), for validate and "
      "compare to find there.");
  cmd->add_option("source", o->source_path,
                  "Config (.toml) or bake (.exr) whose atmosphere to compute (default: the built-in Earth); for a "
                  "spectral one (channels.store = \"spectral\"), each lane group of 4 wavelengths in turn, as "
                  "validate needs them.");
  addReferenceOptions(*cmd, o->queries, o->reference_samples, o->cache_dir);
  cmd->add_option("--piece", o->piece,
                  "K/N: compute only the K-th of N interleaved pieces of the query set (each piece its own job; "
                  "together they are the set).");
  cmd->add_flag("--estimate", o->estimate,
                "Print (JSON) how many of the queries the cache lacks and the core-seconds computing them would "
                "take, and compute nothing.");
  addThreadsOption(*cmd, o->threads);
  return {cmd, [o] { runReference(*o); }};
}

}  // namespace skybake::cli
