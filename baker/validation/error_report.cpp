#include "baker/validation/error_report.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "data_formats/error.h"
#include "data_formats/spectra/spectrum.h"

namespace skybake {

double smallestComparedValue(SunBand band) {
  switch (band) {
    case SunBand::Nautical:
      return kSmallestComparedNauticalValue;
    case SunBand::Astronomical:
    case SunBand::Night:
      return kSmallestComparedAstronomicalValue;
    default:
      return kSmallestComparedValue;
  }
}

namespace {

std::string kilometres(double altitude_m) { return fmt::format("{:.4g}", altitude_m / 1000.0); }

}  // namespace

std::string CameraAltitudeGroup::label() const {
  if (min_m == max_m) return kilometres(min_m) + " km";
  return kilometres(min_m) + " to " + kilometres(max_m) + " km";
}

std::vector<CameraAltitudeGroup> cameraAltitudeGroups(const QuerySet& queries) {
  std::set<double> altitudes;
  for (const RadianceQuery& q : queries.radiance) altitudes.insert(q.altitude_m);
  for (const IrradianceQuery& q : queries.irradiance) altitudes.insert(q.altitude_m);
  const std::vector<double> sorted(altitudes.begin(), altitudes.end());
  // Neighbouring altitudes share a group once there are more than the
  // groups allow: group g holds the sorted altitudes [n g / G, n (g+1) / G).
  const size_t n = sorted.size();
  const size_t group_count = std::min(n, static_cast<size_t>(kMaxCameraAltitudeGroups));
  std::vector<CameraAltitudeGroup> groups;
  for (size_t g = 0; g < group_count; ++g) {
    const size_t first = n * g / group_count, last = n * (g + 1) / group_count - 1;
    groups.push_back({sorted[first], sorted[last]});
  }
  return groups;
}

size_t cameraAltitudeGroupOf(const std::vector<CameraAltitudeGroup>& groups, double altitude_m) {
  for (size_t g = 0; g < groups.size(); ++g) {
    if (altitude_m >= groups[g].min_m && altitude_m <= groups[g].max_m) return g;
  }
  throw Error(ErrorKind::Internal, fmt::format("camera altitude {} m is in no group of the query set", altitude_m));
}

void ErrorStatsBuilder::add(const std::string& quantity, const std::string& band, std::optional<size_t> altitude_group,
                            int channel, double value, double reference, double reference_error,
                            double smallest_compared) {
  auto record = [&](size_t group) {
    Samples& s = samples_[{quantity, band, group}][channel];
    if (!(reference >= smallest_compared)) {
      ++s.skipped;
      return;
    }
    s.signed_errors.push_back((value - reference) / reference);
    s.reference_errors.push_back(reference_error / reference);
  };
  record(kEveryCamera);
  if (altitude_group) record(*altitude_group);
}

std::vector<ErrorRow> ErrorStatsBuilder::rows(int channels, const std::vector<CameraAltitudeGroup>& groups,
                                              bool by_altitude) const {
  static const char* kQuantityOrder[] = {"sky_radiance", "ground_radiance", "radiance_to_point", "transmittance",
                                         "sky_irradiance"};
  std::vector<std::string> band_order;
  for (SunBand band : allSunBands()) band_order.push_back(sunBandName(band));
  band_order.push_back("all");
  std::vector<size_t> group_order;
  if (by_altitude) {
    for (size_t g = 0; g < groups.size(); ++g) group_order.push_back(g);
  } else {
    group_order.push_back(kEveryCamera);
  }
  std::vector<ErrorRow> out;
  for (const char* quantity : kQuantityOrder) {
    for (const std::string& band : band_order) {
      for (size_t group : group_order) {
        auto it = samples_.find({quantity, band, group});
        if (it == samples_.end()) continue;
        ErrorRow row{quantity, band, std::nullopt, {}};
        if (group != kEveryCamera) row.camera_altitude = groups.at(group);
        for (int c = 0; c < channels; ++c) {
          auto sc = it->second.find(c);
          row.channels.push_back(sc == it->second.end() ? ErrorStats{} : summarize(sc->second));
        }
        out.push_back(row);
      }
    }
  }
  return out;
}

ErrorStats ErrorStatsBuilder::summarize(const Samples& s) {
  ErrorStats e;
  e.count = static_cast<int>(s.signed_errors.size());
  e.skipped = s.skipped;
  if (s.signed_errors.empty()) return e;
  double sum2 = 0.0, ref2 = 0.0, sum = 0.0;
  std::vector<double> errors;  // |L - Lref| / Lref
  errors.reserve(s.signed_errors.size());
  for (double x : s.signed_errors) {
    sum += x;
    sum2 += x * x;
    errors.push_back(std::abs(x));
  }
  for (double x : s.reference_errors) ref2 += x * x;
  std::sort(errors.begin(), errors.end());
  e.rms = std::sqrt(sum2 / e.count);
  e.mean = sum / e.count;
  e.max = errors.back();
  // Nearest-rank 95th percentile.
  e.p95 = errors[static_cast<size_t>(std::ceil(0.95 * e.count)) - 1];
  e.reference_standard_error = std::sqrt(ref2 / e.count);
  return e;
}

const ErrorRow* ErrorReport::find(const std::string& quantity, const std::string& band) const {
  for (const ErrorRow& row : rows) {
    if (row.quantity == quantity && row.band == band) return &row;
  }
  return nullptr;
}

namespace {

nlohmann::ordered_json rowsJson(const std::vector<ErrorRow>& rows) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const ErrorRow& row : rows) {
    nlohmann::ordered_json channels = nlohmann::ordered_json::array();
    for (const ErrorStats& s : row.channels) {
      channels.push_back({{"count", s.count},
                          {"skipped", s.skipped},
                          {"rms", s.rms},
                          {"mean", s.mean},
                          {"p95", s.p95},
                          {"max", s.max},
                          {"reference_standard_error", s.reference_standard_error}});
    }
    nlohmann::ordered_json j = {{"quantity", row.quantity}, {"band", row.band}};
    if (row.camera_altitude) {
      j["camera_altitude_m"] = {row.camera_altitude->min_m, row.camera_altitude->max_m};
    }
    j["channels"] = channels;
    out.push_back(j);
  }
  return out;
}

}  // namespace

nlohmann::ordered_json ErrorReport::toJson() const {
  nlohmann::ordered_json j;
  j["query_set"] = query_set;
  j["reference_paths"] = reference_paths;
  j["wavelengths_nm"] = wavelengths_nm;
  j["channels"] = channel_names;
  j["smallest_compared_value"] = smallest_compared_value;
  nlohmann::ordered_json floors;
  for (SunBand band : allSunBands()) {
    floors[sunBandName(band)] = smallestComparedValue(band) * (smallest_compared_value / kSmallestComparedValue);
  }
  j["smallest_compared_value_by_band"] = floors;
  j["errors"] = rowsJson(rows);
  j["errors_by_camera_altitude"] = rowsJson(altitude_rows);
  return j;
}

namespace {

// A channel's name in the table: a wavelength channel's wavelength to 5
// digits ("406.67nm" where the file's channel name, which OpenEXR allows no
// '.' in, is "406p6666666666667nm"); X, Y, Z as they are.
std::vector<std::string> tableLabels(const ErrorReport& r) {
  std::vector<std::string> labels = r.channel_names;
  if (r.wavelengths_nm.size() != labels.size()) return labels;
  for (size_t c = 0; c < labels.size(); ++c) {
    if (labels[c].ends_with("nm")) labels[c] = fmt::format("{:.5g}nm", r.wavelengths_nm[c]);
  }
  return labels;
}

}  // namespace

std::string ErrorReport::table() const {
  // A spectral bake's channels (up to 64) are shown a lane group of 4 at a
  // time, one table per group, each as wide as an ordinary bake's.
  const std::vector<std::string> labels = tableLabels(*this);
  const size_t channels = labels.size();
  const size_t group = static_cast<size_t>(kMaxChannels);
  const size_t groups = (channels + group - 1) / group;
  std::string out;
  for (size_t first = 0; first < channels; first += group) {
    const size_t last = std::min(first + group, channels);
    if (groups > 1) {
      out += fmt::format("{}lane group {} of {} ({} to {}):\n", first == 0 ? "" : "\n", first / group + 1, groups,
                         labels[first], labels[last - 1]);
    }
    out += fmt::format("{:<18} {:<12} {:>5} {:>5}", "quantity", "band", "n", "skip");
    for (size_t c = first; c < last; ++c) out += fmt::format("  {:>22}", labels[c] + " rms/p95/max %");
    out += "  ref stderr %\n";
    for (const ErrorRow& row : rows) {
      const ErrorStats& lead = row.channels[first];
      out += fmt::format("{:<18} {:<12} {:>5} {:>5}", row.quantity, row.band, lead.count, lead.skipped);
      double ref = 0.0;
      for (size_t c = first; c < last; ++c) {
        const ErrorStats& s = row.channels[c];
        out += fmt::format("  {:>22}", fmt::format("{:.2f} / {:.2f} / {:.2f}", 100 * s.rms, 100 * s.p95, 100 * s.max));
        ref = std::max(ref, s.reference_standard_error);
      }
      out += fmt::format("  {:>11.2f}\n", 100 * ref);
    }
    if (altitude_rows.empty()) continue;
    // The same by camera altitude, with the signed mean: a bias at one
    // height shows here even where the rows of every camera average it out.
    out += fmt::format("\nby camera altitude (mean: the signed error, the bias):\n{:<18} {:<12} {:<14} {:>5}",
                       "quantity", "band", "camera", "n");
    for (size_t c = first; c < last; ++c) out += fmt::format("  {:>18}", labels[c] + " rms/mean %");
    out += "  ref stderr %\n";
    for (const ErrorRow& row : altitude_rows) {
      out += fmt::format("{:<18} {:<12} {:<14} {:>5}", row.quantity, row.band, row.camera_altitude->label(),
                         row.channels[first].count);
      double ref = 0.0;
      for (size_t c = first; c < last; ++c) {
        const ErrorStats& s = row.channels[c];
        // A channel whose every value lies below the band's floor has no error to show.
        out += fmt::format(
            "  {:>18}", s.count == 0 ? std::string("-") : fmt::format("{:.2f} / {:+.2f}", 100 * s.rms, 100 * s.mean));
        ref = std::max(ref, s.reference_standard_error);
      }
      out += fmt::format("  {:>11.2f}\n", 100 * ref);
    }
  }
  return out;
}

}  // namespace skybake
