#include "baker/validation/lane_group_validation.h"

#include <fmt/format.h>

#include "data_formats/bake_file/bake_file.h"
#include "data_formats/error.h"

namespace skybake {

std::vector<ReferenceValues> computeLaneGroupReferences(const Sky& sky, const QuerySet& queries,
                                                        const ReferenceSettings& settings, ProgressSink& progress) {
  std::vector<ReferenceValues> out;
  const int groups = sky.laneGroupCount();
  for (int g = 0; g < groups; ++g) {
    const std::string stage = groups == 1 ? "reference" : fmt::format("reference, lane group {}/{}", g + 1, groups);
    out.push_back(computeReferenceValues(sky.laneGroup(g).atmosphere(), queries, settings, progress, stage));
  }
  return out;
}

std::vector<MethodValues> evaluateLaneGroups(const Sky& sky, const QuerySet& queries) {
  std::vector<MethodValues> out;
  for (int g = 0; g < sky.laneGroupCount(); ++g) out.push_back(evaluateBake(sky.laneGroup(g), queries));
  return out;
}

ReferenceValues referenceTotals(const std::vector<ReferenceValues>& groups) {
  ReferenceValues total;
  for (const ReferenceValues& r : groups) {
    total.seconds += r.seconds;
    total.computed += r.computed;
    total.cached += r.cached;
  }
  return total;
}

double secondsPerRay(const std::vector<MethodValues>& groups) {
  double seconds = 0.0;
  for (const MethodValues& m : groups) seconds += m.seconds_per_ray;
  return seconds;
}

ErrorReport compareLaneGroupsWithReference(const Sky& sky, const QuerySet& queries,
                                           const std::vector<ReferenceValues>& references,
                                           const std::vector<MethodValues>& bakes, int reference_paths) {
  const int groups = sky.laneGroupCount();
  if (references.size() != static_cast<size_t>(groups) || bakes.size() != static_cast<size_t>(groups)) {
    throw Error(ErrorKind::Internal, fmt::format("compareLaneGroupsWithReference: {} references and {} bakes for {} "
                                                 "lane groups",
                                                 references.size(), bakes.size(), groups));
  }
  if (groups == 1) return compareWithReference(sky.atmosphere(), queries, references[0], bakes[0], reference_paths);
  std::vector<ErrorReport> reports;
  for (int g = 0; g < groups; ++g) {
    reports.push_back(
        compareWithReference(sky.laneGroup(g).atmosphere(), queries, references[g], bakes[g], reference_paths));
  }
  // Every group answers the same queries, whose quantity, sun band and
  // camera altitude are geometry alone: the groups' reports have the same
  // rows in the same order.
  ErrorReport joined = reports.front();
  joined.wavelengths_nm = sky.atmosphere().wavelengths_nm;
  joined.channel_names = channelNames(sky.atmosphere());
  auto join = [&](std::vector<ErrorRow> ErrorReport::*rows) {
    std::vector<ErrorRow>& joined_rows = joined.*rows;
    for (size_t i = 0; i < joined_rows.size(); ++i) {
      ErrorRow& row = joined_rows[i];
      row.channels.clear();
      for (int g = 0; g < groups; ++g) {
        const std::vector<ErrorRow>& group_rows = reports[g].*rows;
        const size_t lanes = static_cast<size_t>(sky.laneGroup(g).channelCount());
        if (i >= group_rows.size() || group_rows[i].quantity != row.quantity || group_rows[i].band != row.band ||
            group_rows[i].camera_altitude != row.camera_altitude || group_rows[i].channels.size() != lanes) {
          throw Error(ErrorKind::Internal, fmt::format("compareLaneGroupsWithReference: lane group {} has no row {} {}",
                                                       g, row.quantity, row.band));
        }
        row.channels.insert(row.channels.end(), group_rows[i].channels.begin(), group_rows[i].channels.end());
      }
    }
  };
  join(&ErrorReport::rows);
  join(&ErrorReport::altitude_rows);
  return joined;
}

nlohmann::ordered_json laneGroupsJson(const Sky& sky, const std::vector<ReferenceValues>& references) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (int g = 0; g < sky.laneGroupCount(); ++g) {
    const ReferenceValues& r = references.at(static_cast<size_t>(g));
    out.push_back({{"wavelengths_nm", sky.laneGroup(g).atmosphere().wavelengths_nm},
                   {"first_channel", sky.laneGroupFirstChannel(g)},
                   {"reference_cached", r.cached},
                   {"reference_computed", r.computed},
                   {"reference_seconds", r.seconds}});
  }
  return out;
}

}  // namespace skybake
