// skybake info FILE.exr: what a bake holds, from its header.
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "baker/bake/bake_policy.h"
#include "baker/cli/commands.h"
#include "data_formats/bake_file/bake_file.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"
#include "data_formats/parameterization/texture_mapping.h"
#include "data_formats/terminal_text.h"
#include "runtime/sky.h"
#include "runtime/tables/gpu_tables.h"

namespace skybake::cli {
namespace {

// A number of the bake report, or a bad-input error naming the file, the key
// and what the report holds instead (a report is opaque to readers of the
// tables, but info prints it).
double reportNumber(const nlohmann::ordered_json& report, const char* key, const std::string& path) {
  const auto it = report.find(key);
  if (it == report.end()) return 0.0;
  if (!it->is_number()) {
    throwBadInput(
        fmt::format("{} [skybake:bake_report]: {} = {}: must be a number", path, key, terminalSafe(it->dump())));
  }
  return it->get<double>();
}

void printBakeTime(const std::string& report_json, const std::string& path) {
  const nlohmann::ordered_json report = nlohmann::ordered_json::parse(report_json, nullptr, false);
  if (!report.is_object() || !report.contains("wall_seconds")) {
    fmt::print("bake time:     not recorded (reproducible bake)\n");
    return;
  }
  // The stages' time: the file holds its report before it is written, so
  // the whole process's time is in the report sidecar beside it
  // (process_wall_seconds).
  fmt::print("bake time:     {:.2f} s wall in the stages, {:.2f} s CPU, {} threads, peak memory {:.0f} MiB\n",
             reportNumber(report, "wall_seconds", path), reportNumber(report, "cpu_seconds", path),
             reportNumber(report, "threads", path), reportNumber(report, "peak_memory_mib", path));
  const auto stages = report.find("stage_seconds");
  if (stages == report.end()) return;
  if (!stages->is_object()) {
    throwBadInput(fmt::format("{} [skybake:bake_report]: stage_seconds: must be an object of numbers", path));
  }
  for (const auto& [stage, seconds] : stages->items()) {
    if (!seconds.is_number()) {
      throwBadInput(fmt::format("{} [skybake:bake_report]: stage_seconds.{} = {}: must be a number", path,
                                terminalSafe(stage), terminalSafe(seconds.dump())));
    }
    fmt::print("  {:<22} {:8.3f} s\n", terminalSafe(stage), seconds.get<double>());
  }
}

void runInfo(const std::string& path) {
  const BakeFile bake = readBakeFileHeader(path);
  const BakeContents& c = bake.contents;
  const TextureSizes& s = c.sizes;
  // How the bake was made (its name, the sizes its orders iterated on) is in
  // the config it carries as provenance; what it holds is in the attributes.
  const BakeConfig made_from = parseConfig(bake.config_toml, path + " [skybake:config]");
  fmt::print("file:          {}\n", path);
  fmt::print("format:        skybake version {}\n", bake.format_version);
  fmt::print("atmosphere:    {}\n", terminalSafe(made_from.name));
  std::string wavelengths;
  for (double w : c.atmosphere.wavelengths_nm) wavelengths += fmt::format("{} nm  ", w);
  if (c.atmosphere.storesCieXyz()) {
    fmt::print("channels:      X Y Z (CIE 1931 2 deg, W m^-2 sr^-1; 683 Y is luminance in cd m^-2)\n");
    fmt::print("integrated:    {} wavelengths: {}\n", c.atmosphere.wavelengths_nm.size(), wavelengths);
  } else {
    fmt::print("channels:      {}\n", wavelengths);
  }
  if (!c.lane_groups.empty()) {
    // A spectral bake: its lane groups, one pass of the order loop each.
    std::string groups;
    for (const AtmosphereParameters& g : c.lane_groups) {
      std::string nm;
      for (double w : g.wavelengths_nm) nm += fmt::format("{}{}", nm.empty() ? "" : " ", w);
      groups += fmt::format("{}{} nm", groups.empty() ? "" : "; ", nm);
    }
    fmt::print("lane groups:   {} of at most 4 wavelengths, each baked as one pass: {}\n", c.lane_groups.size(),
               groups);
  }
  fmt::print("radii:         bottom {} m, top {} m\n", c.atmosphere.bottom_radius_m, c.atmosphere.top_radius_m);
  fmt::print("sun domain:    zenith 0 to {} deg\n", c.atmosphere.sun_max_zenith_deg);
  fmt::print("orders:        {}\n", bake.orders_computed);
  fmt::print("precision:     {}; FLOAT values keep {} of {} fraction bits (relative rounding at most {:.2g})\n",
             c.precision == StoragePrecision::Half ? "half" : "float", c.stored_fraction_bits, kFloatFractionBits,
             std::ldexp(1.0, -(c.stored_fraction_bits + 1)));
  fmt::print("optical depth: {} mu x {} r\n", s.transmittance_mu, s.transmittance_r);
  if (!c.wavelength_groups.empty()) {
    fmt::print("               and per wavelength ({} wavelengths, for twilight single scattering)\n",
               c.atmosphere.wavelengths_nm.size());
  }
  fmt::print("irradiance:    {} mu_s x {} r\n", s.irradiance_mu_s, s.irradiance_r);
  fmt::print("scattering:    {} r x {} mu x {} mu_s x {} nu (the density: {} mu)\n", s.scattering_r, s.scattering_mu,
             s.scattering_mu_s, s.scattering_nu, c.density_view_size);
  const AtmosphereDomain& d = c.domain;
  if (d.narrowed()) {
    const BakedRanges ranges = bakedRangesOf(d);
    const TextureSizes it = iterationTextureSizes(made_from);
    fmt::print(
        "scene ranges:  altitude {:g} to {:g} m, sun zenith {:g} to {:.2f} deg (the scattering tables; the "
        "orders iterated over the whole atmosphere at {} r x {} mu x {} mu_s x {} nu)\n",
        ranges.altitude_min_m, ranges.altitude_max_m, ranges.sun_zenith_min_deg, ranges.sun_zenith_max_deg,
        it.scattering_r, it.scattering_mu, it.scattering_mu_s, it.scattering_nu);
    // What narrowing buys at these sizes: texels closer together in the
    // axes' own coordinates than a whole-domain bake's.
    fmt::print(
        "               texels {:.2f}x closer in altitude and {:.2f}x in sun angle than a whole-domain bake "
        "of these sizes\n",
        d.horizonToTopDistance() / (d.scattering_rho_max_m - d.scattering_rho_min_m),
        1.0 / (d.scattering_mu_s_coord_max - d.scattering_mu_s_coord_min));
    if (!d.scattering_ground_views) {
      fmt::print(
          "               no views below the horizon: the mu axis holds only the sky, 2x as densely; rays "
          "toward the ground are integrated at lookup (about 20 times slower)\n");
    }
  }
  // What skybake_gl uploads, each choice (runtime/tables/gpu_tables.h).
  constexpr double kMiB = 1024.0 * 1024.0;
  const GpuUploadBytes half = gpuUploadBytes(c, GpuTablePrecision::Half);
  const GpuUploadBytes full = gpuUploadBytes(c, GpuTablePrecision::Float);
  fmt::print(
      "GPU upload:    {:.1f} MiB half (the default: 4D tables {} scaled per (r, mu_s) slice, {:.1f} MiB), "
      "{:.1f} MiB float (4D tables RGBA32F, {:.1f} MiB)\n",
      half.total() / kMiB, c.atmosphere.channelCount() <= 3 ? "RGB16F" : "RGBA16F", half.tables_4d / kMiB,
      full.total() / kMiB, full.tables_4d / kMiB);
  double left_out_mib = 0.0;
  for (const LeftOutPart& p : leftOutParts(c)) {
    fmt::print("left out:      {} ({}), {:.1f} MiB uncompressed\n", p.part, p.reason, p.bytes / (1024.0 * 1024.0));
    left_out_mib += p.bytes / (1024.0 * 1024.0);
  }
  if (left_out_mib > 0.0) {
    fmt::print(
        "               {:.1f} MiB uncompressed saved in all; no bake time (the orders need every table "
        "while iterating)\n",
        left_out_mib);
  }

  printBakeTime(bake.report_json, path);
  fmt::print("\nthe config it was baked from (TOML):\n{}", terminalSafe(bake.config_toml, true));
}

}  // namespace

Command addInfoCommand(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("info", "Print a bake's parameters, sizes and bake report.");
  cmd->add_option("file", *path, "Bake file (.exr).")->required();
  return {cmd, [path] { runInfo(*path); }};
}

}  // namespace skybake::cli
