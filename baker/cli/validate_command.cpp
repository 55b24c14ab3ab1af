// skybake validate FILE.exr [--queries standard|quick|Q.csv] [--reference-samples N] [--json OUT.json]
#include <omp.h>

#include <fmt/format.h>

#include "baker/cli/commands.h"
#include "baker/cli/option_checks.h"
#include "baker/cli/reference_options.h"
#include "baker/cli/report_sidecar.h"
#include "baker/cli/terminal_progress.h"
#include "baker/stages/openmp_threads.h"
#include "baker/validation/validation.h"
#include "data_formats/atomic_file.h"
#include "data_formats/error.h"

namespace skybake::cli {
namespace {

struct ValidateOptions {
  std::string bake_path;
  std::string queries = "standard";
  int reference_samples = ReferenceSettings{}.paths;
  std::string json_path;
  std::string details_path;
  std::string cache_dir;
  bool no_cache = false;
  int threads = 0;
};

// One row per query: the bake's and the reference's values side by side.
void writeDetails(const std::string& path, const AtmosphereParameters& a, const QuerySet& queries,
                  const ReferenceValues& reference, const MethodValues& bake) {
  std::string text = "kind,altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m";
  for (double w : a.wavelengths_nm) text += fmt::format(",bake_{0},reference_{0},reference_error_{0}", w);
  text += "\n";
  const int n = a.channelCount();
  for (size_t i = 0; i < queries.radiance.size(); ++i) {
    const RadianceQuery& q = queries.radiance[i];
    text += fmt::format("radiance,{},{},{},{},{}", q.altitude_m, q.sun_zenith_deg, q.view_zenith_deg,
                        q.view_azimuth_deg, q.distance_m);
    for (int c = 0; c < n; ++c) {
      text += fmt::format(",{:.6g},{:.6g},{:.3g}", bake.radiance[i][c], reference.radiance[i].value[c],
                          reference.radiance[i].standard_error[c]);
    }
    text += "\n";
  }
  for (size_t i = 0; i < queries.irradiance.size(); ++i) {
    const IrradianceQuery& q = queries.irradiance[i];
    text += fmt::format("sky_irradiance,{},{},,,", q.altitude_m, q.sun_zenith_deg);
    for (int c = 0; c < n; ++c) {
      text += fmt::format(",{:.6g},{:.6g},{:.3g}", bake.irradiance[i][c], reference.irradiance[i].value[c],
                          reference.irradiance[i].standard_error[c]);
    }
    text += "\n";
  }
  writeFileContentsAtomically(path, text);
}

void runValidate(const ValidateOptions& o) {
  const ScopedOpenMpThreads thread_count(o.threads);
  for (const std::string& output : {o.json_path, o.details_path}) {
    if (!output.empty()) requireWritableOutput(output, {o.bake_path, o.queries});
  }
  const Sky sky = Sky::load(o.bake_path);
  requireWritableOutput(reportSidecarPath(o.bake_path));
  const AtmosphereParameters& a = sky.atmosphere();
  std::string left_out;
  const QuerySet queries =
      queriesAnsweredBy(sky, querySetNamed(o.queries, a.top_radius_m - a.bottom_radius_m), left_out);
  const ReferenceSettings settings = referenceSettings(o.reference_samples, o.cache_dir, o.no_cache);

  TerminalProgress progress;
  const ReferenceValues reference = computeReferenceValues(a, queries, settings, progress);
  const MethodValues bake = evaluateBake(sky, queries);
  const ErrorReport report = compareWithReference(a, queries, reference, bake, settings.paths);

  fmt::print(
      "validate {} against the reference ({} paths per query), query set '{}': {} radiance and {} "
      "irradiance queries ({} from the cache, {} computed in {:.1f} s)\n",
      o.bake_path, settings.paths, queries.name, queries.radiance.size(), queries.irradiance.size(), reference.cached,
      reference.computed, reference.seconds);
  fmt::print(
      "relative error |L - Lref| / Lref; values below {} skipped ({} nautical, {} astronomical and night); "
      "sun elevation: day > 10 deg, low_sun 0 to 10, twilight (civil) -6 to 0, nautical -12 to -6, "
      "astronomical -18 to -12, night below -18\n\n{}",
      kSmallestComparedValue, kSmallestComparedNauticalValue, kSmallestComparedAstronomicalValue, report.table());
  if (!left_out.empty()) fmt::print("\n{}\n", left_out);

  nlohmann::ordered_json j = report.toJson();
  j["bake_file"] = o.bake_path;
  j["lookup_seconds_per_ray"] = bake.seconds_per_ray;
  if (!o.json_path.empty()) {
    writeFileContentsAtomically(o.json_path, j.dump(2) + "\n");
  }
  if (!o.details_path.empty()) writeDetails(o.details_path, a, queries, reference, bake);
  nlohmann::ordered_json sidecar = readReportSidecar(o.bake_path);
  // A sidecar describes the bake whose report it repeats. One that repeats
  // another (left by a bake interrupted between its two renames, or copied
  // from elsewhere) is not this bake's: it is started anew from the file.
  const nlohmann::ordered_json header_report = nlohmann::ordered_json::parse(sky.bakeReportJson(), nullptr, false);
  if (!sidecar.is_object() || !sidecar.contains("bake") || sidecar["bake"] != header_report) {
    if (!sidecar.empty()) {
      fmt::print(stderr, "skybake validate: {} described another bake; rewritten from {}'s own report\n",
                 reportSidecarPath(o.bake_path).string(), o.bake_path);
    }
    sidecar = {{"bake_file", o.bake_path}, {"bake", header_report}};
  }
  sidecar["validation"] = j;
  writeReportSidecar(o.bake_path, sidecar);
}

}  // namespace

Command addValidateCommand(CLI::App& app) {
  auto o = std::make_shared<ValidateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "validate", "Measure a bake's error against the independent reference solver (results cached on disk).");
  cmd->add_option("file", o->bake_path, "Bake file (.exr).")->required();
  addReferenceOptions(*cmd, o->queries, o->reference_samples, o->cache_dir);
  cmd->add_option("--json", o->json_path, "Also write the report as JSON here.");
  cmd->add_option("--details", o->details_path, "Also write every query's bake and reference values (CSV).");
  cmd->add_flag("--no-cache", o->no_cache, "Compute the reference afresh and keep nothing.");
  addThreadsOption(*cmd, o->threads);
  return {cmd, [o] { runValidate(*o); }};
}

}  // namespace skybake::cli
