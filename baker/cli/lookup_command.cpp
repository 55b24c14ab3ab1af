// skybake lookup radiance|irradiance FILE.exr --queries Q.csv [-o OUT.csv]
#include <iterator>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "baker/cli/commands.h"
#include "baker/validation/validation_queries.h"
#include "data_formats/atomic_file.h"
#include "data_formats/error.h"
#include "data_formats/queries/csv_table.h"
#include "data_formats/queries/local_frame.h"
#include "runtime/sky.h"

namespace skybake::cli {
namespace {

struct LookupOptions {
  std::string bake_path;
  std::string queries_path;
  std::string output_path;  // empty: stdout
};

// The column suffixes of the channels: "680" for 680 nm, or X, Y, Z for a
// colour bake.
std::vector<std::string> channelLabels(const Sky& sky) {
  if (sky.channels().kind == ChannelKind::CieXyz) return sky.channels().names;
  std::vector<std::string> labels;
  for (double w : sky.channels().wavelengths_nm) labels.push_back(fmt::format("{}", w));
  return labels;
}

std::string headerWith(const CsvReader& q, const Sky& sky, std::initializer_list<const char*> prefixes) {
  std::string header;
  for (const std::string& c : q.columns()) header += (header.empty() ? "" : ",") + c;
  const std::vector<std::string> labels = channelLabels(sky);
  for (const char* prefix : prefixes) {
    for (const std::string& label : labels) header += fmt::format(",{}_{}", prefix, label);
  }
  return header + "\n";
}

void appendInputCells(std::string& line, const CsvRow& row) {
  for (size_t c = 0; c < row.texts.size(); ++c) {
    if (c) line += ',';
    line += row.texts[c];
  }
}

void appendChannels(std::string& line, const std::vector<float>& values) {
  for (float v : values) fmt::format_to(std::back_inserter(line), ",{:.9g}", v);
}

// One output row in `line` (reused across rows): the query's own cells, then
// the two looked-up quantities, every channel of each.
const std::string& outputRow(std::string& line, const CsvRow& row, const std::vector<float>& first,
                             const std::vector<float>& second) {
  line.clear();
  appendInputCells(line, row);
  appendChannels(line, first);
  appendChannels(line, second);
  line += '\n';
  return line;
}

// Output problems are found before the queries are read or the bake loaded.
void requireWritableLookupOutput(const LookupOptions& o) {
  if (!o.output_path.empty()) requireWritableOutput(o.output_path, {o.bake_path, o.queries_path});
}

// Refuses, naming the bake, a lookup of an output its scene.outputs left out.
void requireOutput(const std::string& bake_path, bool baked, const char* output) {
  if (!baked) {
    throwBadInput(fmt::format("{}: the bake leaves out {} (its scene.outputs); bake with --outputs including {}",
                              bake_path, output, output));
  }
}

// Refuses, naming the query's cell and the bake, a query outside the bake's
// scene ranges: the lookup would clamp it to the nearest baked altitude or
// sun angle and print a value for a sky it did not bake. A bake of the whole
// domain refuses no sun (below its lowest baked one the night continuation
// takes over) and no camera (one below the ground is looked up on the
// ground, as Sky does), only a point below the ground.
void requireInsideRanges(const CsvReader& q, const CsvRow& row, const RadianceQueryColumns& columns, const Sky& sky,
                         const std::string& bake_path) {
  const BakedRanges& ranges = sky.bakedRanges();
  const AtmosphereParameters& a = sky.atmosphere();
  auto outsideAltitudes = [&] {
    return fmt::format("is outside the altitudes {} covers ({:g} to {:g} m, its scene.altitude_range_m)", bake_path,
                       ranges.altitude_min_m, ranges.altitude_max_m);
  };
  const double altitude_m = row.values[columns.altitude_m];
  if (!ranges.containsAltitude(altitude_m)) q.failCell(row, columns.altitude_m, "m " + outsideAltitudes());
  const double sun_zenith_deg = row.values[columns.sun_zenith_deg];
  if (!ranges.containsSunZenith(sun_zenith_deg)) {
    q.failCell(row, columns.sun_zenith_deg,
               fmt::format("deg is outside the sun angles {} covers ({:g} to {:g} deg, its "
                           "scene.sun_zenith_range_deg)",
                           bake_path, ranges.sun_zenith_min_deg, ranges.sun_zenith_max_deg));
  }
  if (columns.distance_m && row.values[*columns.distance_m] > 0.0) {
    const glm::dvec3 camera = cameraAtAltitude(a.bottom_radius_m, altitude_m);
    const glm::dvec3 view =
        directionFromZenithAzimuthDeg(row.values[columns.view_zenith_deg], row.values[columns.view_azimuth_deg]);
    const double point_altitude_m = glm::length(camera + view * row.values[*columns.distance_m]) - a.bottom_radius_m;
    const bool below_ground = point_altitude_m < -kPointOnGroundTolerance_m;
    if (below_ground || !ranges.containsAltitude(point_altitude_m)) {
      q.failCell(row, *columns.distance_m,
                 fmt::format("m away puts the point at altitude {:.3g} m, which {}", point_altitude_m,
                             below_ground ? std::string("is below the ground") : outsideAltitudes()));
    }
  }
}

// Rows are read, looked up and written one at a time: memory does not grow
// with the number of queries. A bad row stops the lookup with its line and
// column; an output file is then left as it was (standard output has the
// rows before it).
void runRadiance(const LookupOptions& o) {
  requireWritableLookupOutput(o);
  CsvReader q(o.queries_path);
  const RadianceQueryColumns columns = radianceQueryColumns(q);
  const Sky sky = Sky::load(o.bake_path);
  writeCsvOutput(o.output_path, [&](const std::function<void(std::string_view)>& emit) {
    emit(headerWith(q, sky, {"radiance", "transmittance"}));
    std::string line;
    for (CsvRow row; q.next(row);) {
      requireRadianceQueryRanges(q, row, columns);
      const std::vector<double>& v = row.values;
      const glm::dvec3 camera = cameraAtAltitude(sky.atmosphere().bottom_radius_m, v[columns.altitude_m]);
      const glm::dvec3 sun = directionFromZenithAzimuthDeg(v[columns.sun_zenith_deg], 0.0);
      const glm::dvec3 view = directionFromZenithAzimuthDeg(v[columns.view_zenith_deg], v[columns.view_azimuth_deg]);
      const double d = columns.distance_m ? v[*columns.distance_m] : 0.0;
      if (d > 0.0) requireOutput(o.bake_path, sky.outputs().radiance_to_points, "radiance_to_points");
      requireInsideRanges(q, row, columns, sky, o.bake_path);
      // Every channel (a spectral bake's in lane groups of 4).
      const ChannelRadianceAndTransmittance r = sky.everyChannel([&](const Sky& group) {
        return d > 0.0 ? group.radianceToPoint(camera, camera + view * d, sun) : group.skyRadiance(camera, view, sun);
      });
      emit(outputRow(line, row, r.radiance, r.transmittance));
    }
  });
}

void runIrradiance(const LookupOptions& o) {
  requireWritableLookupOutput(o);
  CsvReader q(o.queries_path);
  const size_t altitude = q.require("altitude_m");
  const size_t sun_zenith = q.require("sun_zenith_deg");
  const Sky sky = Sky::load(o.bake_path);
  requireOutput(o.bake_path, sky.outputs().ground_irradiance, "ground_irradiance");
  writeCsvOutput(o.output_path, [&](const std::function<void(std::string_view)>& emit) {
    emit(headerWith(q, sky, {"sky_irradiance", "sun_irradiance"}));
    std::string line;
    for (CsvRow row; q.next(row);) {
      q.requireRange(row, altitude, -kMaxQueryAltitude_m, kMaxQueryAltitude_m);
      q.requireRange(row, sun_zenith, 0.0, kMaxZenithAngle_deg);
      const glm::dvec3 point = cameraAtAltitude(sky.atmosphere().bottom_radius_m, row.values[altitude]);
      const glm::dvec3 sun = directionFromZenithAzimuthDeg(row.values[sun_zenith], 0.0);
      const ChannelSunAndSkyIrradiance e = sky.everyChannel([&](const Sky& group) {
        return group.irradiance(point, {0.0, 0.0, 1.0}, sun);
      });
      emit(outputRow(line, row, e.sky, e.sun));
    }
  });
}

CLI::App* addLookupKind(CLI::App& lookup, const char* name, const char* description, LookupOptions& options) {
  CLI::App* cmd = lookup.add_subcommand(name, description);
  cmd->add_option("file", options.bake_path, "Bake file (.exr).")->required();
  cmd->add_option("--queries", options.queries_path, "Query CSV (columns above).")->required();
  cmd->add_option("-o,--output", options.output_path, "Output CSV (default: standard output).");
  return cmd;
}

}  // namespace

Command addLookupCommand(CLI::App& app) {
  CLI::App* lookup = app.add_subcommand("lookup", "Evaluate a bake at queries from a CSV file.");
  lookup->require_subcommand(1);
  auto radiance = std::make_shared<LookupOptions>();
  auto irradiance = std::make_shared<LookupOptions>();
  CLI::App* radiance_cmd = addLookupKind(
      *lookup, "radiance",
      "Sky radiance and transmittance. Columns: altitude_m, sun_zenith_deg, view_zenith_deg, "
      "view_azimuth_deg (from the sun's azimuth), optional distance_m (> 0: radiance to the point "
      "at that distance; an empty cell is a view ray). Adds radiance_<nm> (W m^-2 sr^-1 nm^-1) and transmittance_<nm>.",
      *radiance);
  CLI::App* irradiance_cmd =
      addLookupKind(*lookup, "irradiance",
                    "Irradiance on a horizontal surface. Columns: altitude_m, sun_zenith_deg. Adds "
                    "sky_irradiance_<nm> and sun_irradiance_<nm> (W m^-2 nm^-1).",
                    *irradiance);
  return {lookup, [=] {
            if (radiance_cmd->parsed()) runRadiance(*radiance);
            if (irradiance_cmd->parsed()) runIrradiance(*irradiance);
          }};
}

}  // namespace skybake::cli
