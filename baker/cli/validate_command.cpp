// skybake validate FILE.exr [--queries standard|quick|Q.csv] [--reference-samples N] [--json OUT.json]
//                          [--colour-config CONFIG.toml]
#include <omp.h>

#include <optional>

#include <fmt/format.h>

#include "baker/cli/commands.h"
#include "baker/cli/option_checks.h"
#include "baker/cli/reference_options.h"
#include "baker/cli/report_sidecar.h"
#include "baker/cli/terminal_progress.h"
#include "baker/stages/openmp_threads.h"
#include "baker/validation/colour_error.h"
#include "baker/validation/colour_reference.h"
#include "baker/validation/lane_group_validation.h"
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
  std::string colour_config;  // empty: no colour error
  bool no_cache = false;
  int threads = 0;
};

// The colour columns of a details row, or nothing without a colour reference.
struct ColourDetails {
  const ColourReferenceValues* reference = nullptr;
  const MethodXyz* bake = nullptr;
};

std::string colourColumns(const colour::Xyz& bake, const CachedReference& reference) {
  return fmt::format(",{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.3g},{:.4g}", bake.x, bake.y, bake.z,
                     reference.value.x, reference.value.y, reference.value.z, reference.standard_error.y,
                     reference.value.y > 0.0
                         ? colourDifference(bake, {reference.value.x, reference.value.y, reference.value.z})
                         : 0.0);
}

// One row per query: the bake's and the reference's values side by side,
// every lane group's channels in order (and their CIE XYZ and CIEDE2000
// with a colour reference).
void writeDetails(const std::string& path, const Sky& sky, const QuerySet& queries,
                  const std::vector<ReferenceValues>& references, const std::vector<MethodValues>& bakes,
                  const ColourDetails& colour) {
  std::string text =
      "kind,altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m,moon_separation_deg,"
      "moon_angular_radius_deg";
  // A colour bake's channels are X, Y, Z: the colour columns below hold them.
  const int groups = sky.atmosphere().storesCieXyz() ? 0 : sky.laneGroupCount();
  auto lanes = [&](int g) { return sky.laneGroup(g).channelCount(); };
  for (int g = 0; g < groups; ++g) {
    for (int c = 0; c < lanes(g); ++c) {
      text +=
          fmt::format(",bake_{0},reference_{0},reference_error_{0}", sky.laneGroup(g).atmosphere().wavelengths_nm[c]);
    }
  }
  if (colour.reference != nullptr) {
    text += ",bake_X,bake_Y,bake_Z,reference_X,reference_Y,reference_Z,reference_error_Y,ciede2000";
  }
  text += "\n";
  for (size_t i = 0; i < queries.radiance.size(); ++i) {
    const RadianceQuery& q = queries.radiance[i];
    text += fmt::format("radiance,{},{},{},{},{},{},{}", q.altitude_m, q.sun_zenith_deg, q.view_zenith_deg,
                        q.view_azimuth_deg, q.distance_m, q.moon.separation_deg, q.moon.angular_radius_deg);
    for (int g = 0; g < groups; ++g) {
      const CachedReference& r = references[g].radiance[i];
      for (int c = 0; c < lanes(g); ++c) {
        text += fmt::format(",{:.6g},{:.6g},{:.3g}", bakes[g].radiance[i][c], r.value[c], r.standard_error[c]);
      }
    }
    if (colour.reference != nullptr) text += colourColumns(colour.bake->radiance[i], colour.reference->radiance[i]);
    text += "\n";
  }
  for (size_t i = 0; i < queries.irradiance.size(); ++i) {
    const IrradianceQuery& q = queries.irradiance[i];
    text += fmt::format("sky_irradiance,{},{},,,,{},{}", q.altitude_m, q.sun_zenith_deg, q.moon.separation_deg,
                        q.moon.angular_radius_deg);
    for (int g = 0; g < groups; ++g) {
      const CachedReference& r = references[g].irradiance[i];
      for (int c = 0; c < lanes(g); ++c) {
        text += fmt::format(",{:.6g},{:.6g},{:.3g}", bakes[g].irradiance[i][c], r.value[c], r.standard_error[c]);
      }
    }
    if (colour.reference != nullptr) {
      text += colourColumns(colour.bake->irradiance[i], colour.reference->irradiance[i]);
    }
    text += "\n";
  }
  writeFileContentsAtomically(path, text);
}

void runValidate(const ValidateOptions& o) {
  const ScopedOpenMpThreads thread_count(o.threads);
  for (const std::string& output : {o.json_path, o.details_path}) {
    if (!output.empty()) requireWritableOutput(output, {o.bake_path, o.queries, o.colour_config});
  }
  const Sky sky = Sky::load(o.bake_path);
  requireWritableOutput(reportSidecarPath(o.bake_path));
  const AtmosphereParameters& a = sky.atmosphere();
  // A colour bake's X, Y, Z are compared with the colour reference only:
  // its atmosphere's X, Y, Z coefficients are means no wavelength has.
  const bool colour_bake = a.storesCieXyz();
  if (colour_bake && o.colour_config.empty()) {
    throwBadInput(fmt::format(
        "{}: a colour bake (channels X, Y, Z): validate compares it with the colour reference, which needs the "
        "config it was made from: add --colour-config CONFIG.toml",
        o.bake_path));
  }
  // A config that cannot give the colour reference is refused before any
  // reference is computed.
  std::optional<ColourReferenceAtmospheres> colour_atmospheres;
  if (!o.colour_config.empty()) {
    requireConfigOfBake(o.colour_config, a, sky.contents().lane_groups);
    colour_atmospheres = colourReferenceAtmospheresFromFile(o.colour_config);
  }
  std::string left_out;
  const QuerySet queries =
      queriesAnsweredBy(sky, querySetNamed(o.queries, a.bottom_radius_m, a.top_radius_m), left_out);
  const ReferenceSettings settings = referenceSettings(o.reference_samples, o.cache_dir, o.no_cache);

  TerminalProgress progress;
  ColourReferenceValues colour_reference;
  if (colour_atmospheres) colour_reference = computeColourReference(*colour_atmospheres, queries, settings, progress);
  // A colour bake's reference is the colour reference itself, channel for
  // channel; any other bake's is computed per lane group (a spectral bake's
  // groups one after the other, each in its own cache).
  const std::vector<ReferenceValues> references =
      colour_bake
          ? std::vector<ReferenceValues>{{colour_reference.radiance, colour_reference.irradiance,
                                          colour_reference.seconds, colour_reference.computed, colour_reference.cached}}
          : computeLaneGroupReferences(sky, queries, settings, progress);
  const ReferenceValues reference = referenceTotals(references);
  const std::vector<MethodValues> bakes = evaluateLaneGroups(sky, queries);
  const ErrorReport report = compareLaneGroupsWithReference(sky, queries, references, bakes, settings.paths);
  MethodXyz bake_xyz;
  ColourValidation colour_report;
  if (colour_atmospheres) {
    bake_xyz = bakeXyz(sky, bakes);
    colour_report =
        colour_bake
            ? ColourValidation{compareColourWithReference(a, queries, colour_reference, bake_xyz, settings.paths), {}}
            : validateColour(sky, queries, references, colour_reference, bakes, settings.paths);
  }

  // The X, Y, Z of a colour bake are spectral values integrated over the
  // colour-matching functions' width: its thresholds scale with it.
  const double value_scale = report.smallest_compared_value / kSmallestComparedValue;
  const int groups = sky.laneGroupCount();
  fmt::print(
      "validate {} against the reference ({} paths per query, {} times that for rays to points with the sun "
      "below the horizon{}), query set '{}': {} radiance and {} irradiance queries ({} from the cache, {} computed "
      "in {:.1f} s)\n",
      o.bake_path, settings.paths, kTwilightPointRayPathFactor,
      groups > 1 ? fmt::format("; {} lane groups of up to 4 wavelengths, each against its own reference", groups) : "",
      queries.name, queries.radiance.size(), queries.irradiance.size(), reference.cached, reference.computed,
      reference.seconds);
  fmt::print(
      "relative error |L - Lref| / Lref; values below {:.3g} skipped ({:.3g} nautical, {:.3g} astronomical and "
      "night); sun elevation: day > 10 deg, low_sun 0 to 10, twilight (civil) -6 to 0, nautical -12 to -6, "
      "astronomical -18 to -12, night below -18\n\n{}",
      report.smallest_compared_value, kSmallestComparedNauticalValue * value_scale,
      kSmallestComparedAstronomicalValue * value_scale, report.table());
  if (colour_atmospheres) {
    fmt::print(
        "\ncolour against the reference in CIE XYZ from {} wavelengths, {:g} to {:g} nm ({} from the cache, {} "
        "computed in {:.1f} s): luminance |Y - Yref| / Yref; CIEDE2000 with both scaled so that the reference "
        "has L* = {:g} (sRGB white); reference Y below {:.3g} skipped (as above, times the colour-matching "
        "functions' width)\n\n{}",
        kColourReferenceWavelengthCount, kColourReferenceFirst_nm, kColourReferenceLast_nm, colour_reference.cached,
        colour_reference.computed, colour_reference.seconds, kComparedLightness, smallestComparedY(SunBand::Day),
        colour_report.bake.table());
    if (!colour_bake) {
      fmt::print(
          "\nthe same for the spectral reference at the bake's own wavelengths (a bake without table error: what "
          "sampling the spectrum there costs)\n\n{}",
          colour_report.sampling.table());
    }
  }
  if (!left_out.empty()) fmt::print("\n{}\n", left_out);

  nlohmann::ordered_json j = report.toJson();
  if (colour_atmospheres) {
    j["colour"] = colour_report.toJson();
    j["colour"]["config"] = o.colour_config;
  }
  if (groups > 1) j["lane_groups"] = laneGroupsJson(sky, references);
  j["bake_file"] = o.bake_path;
  j["lookup_seconds_per_ray"] = secondsPerRay(bakes);
  if (!o.json_path.empty()) {
    writeFileContentsAtomically(o.json_path, j.dump(2) + "\n");
  }
  if (!o.details_path.empty()) {
    writeDetails(o.details_path, sky, queries, references, bakes,
                 colour_atmospheres ? ColourDetails{&colour_reference, &bake_xyz} : ColourDetails{});
  }
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
  cmd->add_option("file", o->bake_path,
                  "Bake file (.exr). A spectral bake (channels.store = \"spectral\") is validated lane group by lane "
                  "group, each group of 4 wavelengths against its own reference (the reference time grows with the "
                  "number of groups); the report gives every wavelength's errors.")
      ->required();
  addReferenceOptions(*cmd, o->queries, o->reference_samples, o->cache_dir);
  cmd->add_option("--json", o->json_path, "Also write the report as JSON here.");
  cmd->add_option("--details", o->details_path, "Also write every query's bake and reference values (CSV).");
  cmd->add_option("--colour-config", o->colour_config,
                  "Also report colour error (luminance, CIEDE2000) against a reference in CIE XYZ from 41 "
                  "wavelengths, 380 to 780 nm, the atmosphere there read from this config's spectra: the config "
                  "the bake was made from (a spectral bake's colour is all its channels together). Refused for a "
                  "config with a per-wavelength key given as a list of "
                  "differing values, or a spectrum that stops short of 380 or 780 nm (docs/COLOUR.md). Required for a "
                  "colour bake (channels X, Y, Z), which is compared with this reference only.");
  cmd->add_flag("--no-cache", o->no_cache, "Compute the reference afresh and keep nothing.");
  addThreadsOption(*cmd, o->threads);
  return {cmd, [o] { runValidate(*o); }};
}

}  // namespace skybake::cli
