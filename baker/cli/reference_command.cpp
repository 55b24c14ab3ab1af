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
#include "data_formats/config.h"
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

AtmosphereParameters atmosphereOf(const std::string& path) {
  if (path.empty()) return builtinEarthConfig().atmosphere;
  const AtmosphereParameters a = std::filesystem::path(path).extension() == ".exr" ? Sky::load(path).atmosphere()
                                                                                   : loadConfigFile(path).atmosphere;
  requireWavelengthChannels(a, path, "reference");
  return a;
}

void runReference(const ReferenceOptions& o) {
  const ScopedOpenMpThreads thread_count(o.threads);
  const Piece piece = parsePiece(o.piece);
  const AtmosphereParameters a = atmosphereOf(o.source_path);
  const QuerySet queries =
      queryPiece(querySetNamed(o.queries, a.top_radius_m - a.bottom_radius_m), piece.index, piece.count);
  const ReferenceSettings settings = referenceSettings(o.reference_samples, o.cache_dir, false);
  const std::string source = o.source_path.empty() ? "<built-in earth>" : o.source_path;
  if (o.estimate) {
    const ReferenceCache cache(settings.cache_directory, a, settings.paths);
    const size_t missing = queriesMissingFromCache(cache, queries).size();
    const size_t total = queries.radiance.size() + queries.irradiance.size();
    const nlohmann::ordered_json j{
        {"source", source},
        {"query_set", queries.name},
        {"piece", fmt::format("{}/{}", piece.index, piece.count)},
        {"paths_per_query", settings.paths},
        {"queries", total},
        {"cached", total - missing},
        {"to_compute", missing},
        {"estimated_core_seconds", std::ceil(missing * double(settings.paths) * kReferenceCoreSecondsPerPath)},
        {"cache_directory", cache.directory().string()}};
    fmt::print("{}\n", j.dump(2));
    return;
  }
  TerminalProgress progress;
  const ReferenceValues reference = computeReferenceValues(a, queries, settings, progress);
  fmt::print(
      "reference for {} ({} paths per query), query set '{}' piece {} of {}: {} radiance and {} irradiance "
      "queries ({} from the cache, {} computed in {:.1f} s) in {}\n",
      source, settings.paths, queries.name, piece.index, piece.count, queries.radiance.size(),
      queries.irradiance.size(), reference.cached, reference.computed, reference.seconds,
      settings.cache_directory.string());
}

}  // namespace

Command addReferenceCommand(CLI::App& app) {
  auto o = std::make_shared<ReferenceOptions>();
  CLI::App* cmd = app.add_subcommand(
      "reference",
      "Compute an atmosphere's reference values into the reference cache (whole or one piece), for validate and "
      "compare to find there.");
  cmd->add_option("source", o->source_path,
                  "Config (.toml) or bake (.exr) whose atmosphere to compute (default: the built-in Earth).");
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
