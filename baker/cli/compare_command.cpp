// skybake compare [CONFIG.toml] [--queries quick|standard|Q.csv] [--resolutions 0.5,1,2]
// skybake compare COLOUR_CONFIG.toml --colour [--queries ...]
// Error against the reference and cost, for the bake at several resolutions
// and for the simpler methods people use instead, on the same queries; or,
// with --colour, a colour bake beside bakes of 3 and 4 wavelengths of the
// same atmosphere and its spectral bake (every one of its wavelengths
// stored), in colour error against the colour reference.
#include <omp.h>

#include <array>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "baker/bake/bake.h"
#include "baker/cli/available_memory.h"
#include "baker/cli/bake_memory_estimate.h"
#include "baker/cli/commands.h"
#include "baker/cli/option_checks.h"
#include "baker/cli/terminal_progress.h"
#include "baker/cli/wavelength_channels.h"
#include "baker/comparators/flat_closed_form.h"
#include "baker/comparators/hillaire_multiple_scattering.h"
#include "baker/comparators/ray_marched_single.h"
#include "baker/validation/colour_error.h"
#include "baker/validation/colour_reference.h"
#include "baker/validation/lane_group_validation.h"
#include "baker/validation/validation.h"
#include "data_formats/atomic_file.h"
#include "data_formats/config/config.h"
#include "data_formats/config/config_at_wavelengths.h"
#include "data_formats/error.h"

namespace skybake::cli {
namespace {

struct CompareOptions {
  std::string config_path;
  std::string queries = "standard";
  int reference_samples = ReferenceSettings{}.paths;
  std::vector<double> resolutions = {0.5, 1.0, 2.0};
  std::string json_path;
  std::string cache_dir;
  bool no_cache = false;
  bool colour = false;
  bool resolutions_given = false;
};

// The bake as a method.
class BakedSky final : public SkyMethod {
 public:
  BakedSky(std::string name, BakeOutput bake)
      : name_(std::move(name)), seconds_(bake.report.wall_seconds), sky_(std::move(bake.file)) {}
  std::string name() const override { return name_; }
  RadianceAndTransmittance received(const glm::dvec3& camera, const glm::dvec3& view,
                                    const glm::dvec3& sun) const override {
    return sky_.receivedRadiance(camera, view, sun);
  }
  double precomputeSeconds() const override { return seconds_; }
  const Sky& sky() const { return sky_; }
  // Every lane group's tables (a spectral bake holds one set per group of 4).
  size_t memoryBytes() const override {
    size_t bytes = 0;
    for (int g = 0; g < sky_.laneGroupCount(); ++g) {
      const Sky& group = sky_.laneGroup(g);
      const BakeTables& t = group.tables();
      size_t texels = 0;
      for (const auto* v : {&t.optical_depth.texels, &t.irradiance.texels, &t.single_rayleigh.texels,
                            &t.single_mie.texels, &t.multiple_scattering.texels, &t.multiple_density.texels}) {
        texels += v->size();
      }
      bytes += texels * sizeof(float) * group.channelCount();
    }
    return bytes;
  }

 private:
  std::string name_;
  double seconds_;
  Sky sky_;
};

// --resolutions: below 1/20 of a table there is nothing left to compare;
// above 8x the bake of a default-size config needs tens of GiB and hours.
constexpr double kMinResolutionFactor = 0.05;
constexpr double kMaxResolutionFactor = 8.0;

int scaled(int size, double factor, int minimum, bool even) {
  int s = std::max(minimum, static_cast<int>(std::lround(size * factor)));
  if (even && s % 2 != 0) ++s;
  return s;
}

TextureSizes scaledSizes(const TextureSizes& s, double f) {
  TextureSizes out;
  out.transmittance_mu = scaled(s.transmittance_mu, f, 2, false);
  out.transmittance_r = scaled(s.transmittance_r, f, 2, false);
  out.irradiance_mu_s = scaled(s.irradiance_mu_s, f, 2, false);
  out.irradiance_r = scaled(s.irradiance_r, f, 2, false);
  out.scattering_r = scaled(s.scattering_r, f, 2, false);
  out.scattering_mu = scaled(s.scattering_mu, f, 4, true);
  out.scattering_mu_s = scaled(s.scattering_mu_s, f, 2, false);
  out.scattering_nu = scaled(s.scattering_nu, f, 2, false);
  return out;
}

MethodValues evaluate(const SkyMethod& method, const AtmosphereParameters& a, const QuerySet& queries) {
  MethodValues out;
  const auto start = std::chrono::steady_clock::now();
  for (const RadianceQuery& q : queries.radiance) {
    const QueryGeometry g = geometryOf(a, q);
    const RadianceAndTransmittance v = method.received(g.camera, g.view, g.sun);
    out.radiance.push_back(v.radiance);
    out.transmittance.push_back(v.transmittance);
  }
  out.seconds_per_ray = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
                        std::max<size_t>(queries.radiance.size(), 1);
  return out;
}

// The queries the comparators answer: rays to the sky or the ground without
// a moon. Rays to a point, eclipses (the comparators have no moon) and
// irradiance are validate's: left out, with their counts in `left_out`
// (empty when none is). A set with nothing left is refused.
QuerySet comparableQueries(const QuerySet& all, const std::string& what, std::string& left_out) {
  QuerySet queries{all.name, {}, {}};
  size_t eclipses = 0, to_points = 0;
  for (const RadianceQuery& q : all.radiance) {
    if (q.moon.present()) {
      ++eclipses;
    } else if (q.distance_m > 0.0) {
      ++to_points;
    } else {
      queries.radiance.push_back(q);
    }
  }
  size_t irradiance = 0;
  for (const IrradianceQuery& q : all.irradiance) ++(q.moon.present() ? eclipses : irradiance);
  std::vector<std::string> parts;
  if (eclipses > 0) parts.push_back(fmt::format("{} eclipse queries (a moon; the comparators have no moon)", eclipses));
  if (to_points > 0) parts.push_back(fmt::format("{} rays to points", to_points));
  if (irradiance > 0) parts.push_back(fmt::format("{} irradiance queries", irradiance));
  left_out.clear();
  for (const std::string& part : parts) left_out += (left_out.empty() ? "" : ", ") + part;
  if (queries.radiance.empty()) {
    throwBadInput(fmt::format("{}: {} holds no sky or ground ray without a moon to compare ({}): use skybake validate",
                              what, all.name, left_out.empty() ? "no radiance queries" : left_out));
  }
  if (!left_out.empty()) left_out = "left out (skybake validate compares them): " + left_out;
  return queries;
}

// Worst channel's figure in a row, or -1 where the row is absent.
double worst(const ErrorReport& r, const char* quantity, const char* band, double ErrorStats::*field) {
  const ErrorRow* row = r.find(quantity, band);
  if (row == nullptr) return -1.0;
  double w = 0.0;
  for (const ErrorStats& s : row->channels) w = std::max(w, s.*field);
  return w;
}

std::string bandCell(const ErrorReport& r, const char* quantity, const char* band) {
  const double rms = worst(r, quantity, band, &ErrorStats::rms);
  if (rms < 0.0) return "-";
  return fmt::format("{:.1f} / {:.1f} / {:.0f}", 100 * rms, 100 * worst(r, quantity, band, &ErrorStats::p95),
                     100 * worst(r, quantity, band, &ErrorStats::max));
}

// The config at each --resolutions factor, each checked like a config file,
// and all of them together checked against the machine's memory: every bake
// is kept until the comparison ends.
std::vector<BakeConfig> scaledConfigs(const BakeConfig& config, const std::string& source,
                                      const std::vector<double>& factors) {
  std::vector<BakeConfig> scaled;
  uint64_t kept_bytes = 0;
  uint64_t largest_extra_bytes = 0;  // the most any one bake needs beyond what it keeps
  for (double factor : factors) {
    BakeConfig c = config;
    c.sizes = scaledSizes(config.sizes, factor);
    validateConfig(c, fmt::format("{} at --resolutions = {}", source, factor));
    const BakeMemoryEstimate memory = estimateBakeMemory(c);
    kept_bytes += memory.kept_bytes;
    largest_extra_bytes = std::max(largest_extra_bytes, memory.peak_bytes - memory.kept_bytes);
    scaled.push_back(std::move(c));
  }
  std::string list;
  for (double factor : factors) list += fmt::format("{}{}", list.empty() ? "" : ",", factor);
  requireMemoryAvailable(
      fmt::format("{}: --resolutions = {}: the comparison (every bake kept to the end)", source, list),
      kept_bytes + largest_extra_bytes);
  return scaled;
}

// The wavelengths a colour comparison bakes as wavelength files: the
// built-in Earth's three, and four evenly spread over the visible (the most
// one file holds).
constexpr std::array<double, 3> kThreeCompareWavelengths_nm = {680.0, 550.0, 440.0};
constexpr std::array<double, 4> kFourCompareWavelengths_nm = {440.0, 520.0, 600.0, 680.0};

std::string colourCell(const ColourErrorReport& r, const char* band) {
  const ColourErrorRow* row = r.find("sky_radiance", band);
  if (row == nullptr || row->stats.count == 0) return "-";
  return fmt::format("{:.2f} % / {:.2f} / {:.2f}", 100 * row->stats.luminance_rms, row->stats.ciede2000_median,
                     row->stats.ciede2000_p95);
}

// --colour: the config's colour bake, its atmosphere baked on 3 and on 4
// wavelengths, and its spectral bake of the colour bake's wavelengths, each
// against the colour reference (41 wavelengths, CIE XYZ), in luminance and
// CIEDE2000, with bake time, lookup time (every lane group's) and table size
// (every lane group's tables).
void runColourCompare(const CompareOptions& o) {
  if (o.config_path.empty() || o.resolutions_given) {
    throwBadInput(o.config_path.empty()
                      ? std::string("compare --colour: give a colour bake's config (channels.store = \"cie_xyz\" "
                                    "with spectra, e.g. data_formats/presets/earth_colour.toml)")
                      : std::string("compare --colour: --resolutions does not apply (the bakes are compared at the "
                                    "config's sizes)"));
  }
  const BakeConfig colour_config = loadConfigFile(o.config_path);
  if (!colour_config.atmosphere.storesCieXyz()) {
    throwBadInput(
        fmt::format("{}: compare --colour needs a colour bake's config (channels.store = \"cie_xyz\")", o.config_path));
  }
  // The colour reference first: it refuses a config without spectra.
  const ColourReferenceAtmospheres colour_atmospheres = colourReferenceAtmospheresFromFile(o.config_path);
  struct Variant {
    std::string name;
    BakeConfig config;
  };
  std::vector<Variant> variants;
  variants.push_back(
      {"3 wavelengths (680, 550, 440 nm)", configFileAtWavelengths(o.config_path, kThreeCompareWavelengths_nm)});
  variants.push_back(
      {"4 wavelengths (440, 520, 600, 680 nm)", configFileAtWavelengths(o.config_path, kFourCompareWavelengths_nm)});
  const size_t colour_wavelengths = colour_config.atmosphere.wavelengths_nm.size();
  variants.push_back({fmt::format("colour: {} wavelengths to CIE XYZ", colour_wavelengths), colour_config});
  // The colour bake's wavelengths every one stored, its colour converted
  // after the lookups: the truth the colour bake approximates.
  const BakeConfig spectral_config = configFileWithStore(o.config_path, "spectral");
  variants.push_back({fmt::format("spectral: {} wavelengths, {} lane groups", colour_wavelengths,
                                  (colour_wavelengths + kMaxChannels - 1) / kMaxChannels),
                      spectral_config});
  uint64_t largest_peak_bytes = 0;  // the bakes run one at a time
  for (const Variant& v : variants)
    largest_peak_bytes = std::max(largest_peak_bytes, estimateBakeMemory(v.config).peak_bytes);
  requireMemoryAvailable(fmt::format("{}: compare --colour (one bake at a time)", o.config_path), largest_peak_bytes);

  const AtmosphereParameters& geometry = variants.front().config.atmosphere;
  const QuerySet all = querySetNamed(o.queries, geometry.bottom_radius_m, geometry.top_radius_m);
  std::string left_out;
  const QuerySet queries = comparableQueries(all, "compare --colour", left_out);
  TerminalProgress progress;
  const ReferenceSettings settings = referenceSettings(o.reference_samples, o.cache_dir, o.no_cache);
  const ColourReferenceValues reference = computeColourReference(colour_atmospheres, queries, settings, progress);

  fmt::print(
      "compare in colour on '{}' ({} sky and ground rays; colour reference from {} wavelengths, {} paths per "
      "query); sky radiance: luminance RMS / CIEDE2000 median / p95; {} cores\n\n",
      queries.name, queries.radiance.size(), kColourReferenceWavelengthCount, settings.paths, omp_get_num_procs());
  if (!left_out.empty()) fmt::print("{}\n\n", left_out);
  fmt::print("{:<40} {:>10} {:>9} {:>9}  {:>24} {:>24} {:>24}\n", "bake", "bake s", "us/ray", "MiB", "sky day",
             "sky low sun", "sky twilight");
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const Variant& v : variants) {
    SilentProgress silent;
    fmt::print(stderr, "baking {} ...\n", v.name);
    const BakedSky baked(v.name, bakeAtmosphere(v.config, 0, silent));
    // Every lane group's lookups (a spectral bake's colour is its groups' channels together).
    const std::vector<MethodValues> values = evaluateLaneGroups(baked.sky(), queries);
    const double seconds_per_ray = secondsPerRay(values);
    const ColourErrorReport report = compareColourWithReference(baked.sky().atmosphere(), queries, reference,
                                                                bakeXyz(baked.sky(), values), settings.paths);
    fmt::print("{:<40} {:>10.2f} {:>9.2f} {:>9.2f}  {:>24} {:>24} {:>24}\n", v.name, baked.precomputeSeconds(),
               seconds_per_ray * 1e6, baked.memoryBytes() / (1024.0 * 1024.0), colourCell(report, "day"),
               colourCell(report, "low_sun"), colourCell(report, "twilight"));
    nlohmann::ordered_json row = report.toJson();
    row["method"] = v.name;
    row["precompute_seconds"] = baked.precomputeSeconds();
    row["seconds_per_ray"] = seconds_per_ray;
    row["memory_bytes"] = baked.memoryBytes();
    rows.push_back(row);
  }
  if (!o.json_path.empty()) {
    writeFileContentsAtomically(
        o.json_path, nlohmann::ordered_json{{"cores", omp_get_num_procs()}, {"methods", rows}}.dump(2) + "\n");
  }
}

void runCompare(const CompareOptions& o) {
  if (!o.json_path.empty()) requireWritableOutput(o.json_path, {o.config_path, o.queries});
  if (o.colour) {
    runColourCompare(o);
    return;
  }
  const BakeConfig config = o.config_path.empty() ? builtinEarthConfig() : loadConfigFile(o.config_path);
  const AtmosphereParameters& a = config.atmosphere;
  requireOneLaneGroupForComparators(a, o.config_path);
  requireWavelengthChannels(a, o.config_path, "compare");
  const std::vector<BakeConfig> scaled_configs =
      scaledConfigs(config, o.config_path.empty() ? "<built-in earth>" : o.config_path, o.resolutions);
  const QuerySet all = querySetNamed(o.queries, a.bottom_radius_m, a.top_radius_m);
  std::string left_out;
  const QuerySet queries = comparableQueries(all, "compare", left_out);

  TerminalProgress progress;
  const ReferenceSettings settings = referenceSettings(o.reference_samples, o.cache_dir, o.no_cache);
  const ReferenceValues reference = computeReferenceValues(a, queries, settings, progress);

  std::vector<std::unique_ptr<SkyMethod>> methods;
  methods.push_back(std::make_unique<RayMarchedSingleScattering>(a));
  methods.push_back(std::make_unique<FlatClosedFormSingleScattering>(a));
  methods.push_back(std::make_unique<HillaireMultipleScattering>(a));
  for (size_t i = 0; i < o.resolutions.size(); ++i) {
    const BakeConfig& scaled_config = scaled_configs[i];
    const TextureSizes& s = scaled_config.sizes;
    SilentProgress silent;
    fmt::print(stderr, "baking at {}x the configured sizes ...\n", o.resolutions[i]);
    methods.push_back(
        std::make_unique<BakedSky>(fmt::format("skybake {}x{}x{}x{}, {} orders", s.scattering_r, s.scattering_mu,
                                               s.scattering_mu_s, s.scattering_nu, config.bake.orders),
                                   bakeAtmosphere(scaled_config, 0, silent)));
  }

  fmt::print(
      "compare on '{}' ({} sky and ground rays; reference {} paths per query); errors: RMS / p95 / max %, "
      "worst channel; {} cores\n\n",
      queries.name, queries.radiance.size(), settings.paths, omp_get_num_procs());
  if (!left_out.empty()) fmt::print("{}\n\n", left_out);
  fmt::print("{:<62} {:>10} {:>9} {:>9}  {:>16} {:>16} {:>16}  {:>16}\n", "method", "precomp s", "us/ray", "MiB",
             "sky day", "sky low sun", "sky twilight", "ground day");
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const auto& method : methods) {
    const MethodValues values = evaluate(*method, a, queries);
    const ErrorReport report = compareWithReference(a, queries, reference, values, settings.paths);
    fmt::print("{:<62} {:>10.2f} {:>9.2f} {:>9.2f}  {:>16} {:>16} {:>16}  {:>16}\n", method->name(),
               method->precomputeSeconds(), values.seconds_per_ray * 1e6, method->memoryBytes() / (1024.0 * 1024.0),
               bandCell(report, "sky_radiance", "day"), bandCell(report, "sky_radiance", "low_sun"),
               bandCell(report, "sky_radiance", "twilight"), bandCell(report, "ground_radiance", "day"));
    nlohmann::ordered_json row = report.toJson();
    row["method"] = method->name();
    row["precompute_seconds"] = method->precomputeSeconds();
    row["seconds_per_ray"] = values.seconds_per_ray;
    row["memory_bytes"] = method->memoryBytes();
    rows.push_back(row);
  }
  if (!o.json_path.empty()) {
    writeFileContentsAtomically(
        o.json_path, nlohmann::ordered_json{{"cores", omp_get_num_procs()}, {"methods", rows}}.dump(2) + "\n");
  }
}

}  // namespace

Command addCompareCommand(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "Error against the reference and cost of the bake at several resolutions and of the simpler methods.");
  cmd->add_option("config", o->config_path, "Atmosphere config (default: the built-in Earth).");
  cmd->add_option("--queries", o->queries, "standard, quick or a CSV (see validate).")->capture_default_str();
  requireWholeIn(cmd->add_option("--reference-samples", o->reference_samples,
                                 "Monte Carlo paths per reference query (see validate).")
                     ->capture_default_str(),
                 1, kMaxReferencePaths);
  CLI::Option* resolutions =
      cmd->add_option("--resolutions", o->resolutions, "Bake at these multiples of the configured table sizes.")
          ->delimiter(',');
  requireFiniteIn(resolutions, kMinResolutionFactor, kMaxResolutionFactor);
  cmd->add_flag("--colour", o->colour,
                "CONFIG is a colour bake's (channels.store = \"cie_xyz\", with spectra): compare it with its "
                "atmosphere baked on 3 and on 4 wavelengths and with its spectral bake of the same wavelengths "
                "(channels.store = \"spectral\", colour converted after the lookups), in luminance and CIEDE2000 "
                "against a colour reference from 41 wavelengths (docs/COLOUR.md), with bake time, lookup time and "
                "size.");
  cmd->add_option("--json", o->json_path, "Also write the table as JSON here.");
  cmd->add_option("--cache-dir", o->cache_dir, "Reference cache directory (see validate).");
  cmd->add_flag("--no-cache", o->no_cache, "Compute the reference afresh and keep nothing.");
  return {cmd, [o, resolutions] {
            o->resolutions_given = resolutions->count() > 0;
            runCompare(*o);
          }};
}

}  // namespace skybake::cli
