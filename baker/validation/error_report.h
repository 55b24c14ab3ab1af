// Relative errors against the reference, summarised per quantity and sun
// band, and per camera altitude as well, so that a bias at one height is not
// hidden in the average over all of them.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "baker/validation/validation_queries.h"

namespace skybake {

// Reference values below this radiance (W m^-2 sr^-1 nm^-1), irradiance
// (W m^-2 nm^-1) or transmittance are left out of relative errors: deep in
// twilight or behind a thick atmosphere a relative error of a value this
// small says nothing a renderer could show. They are counted as skipped.
inline constexpr double kSmallestComparedValue = 1e-5;
// The same floor in nautical and astronomical twilight, where the whole sky
// lies 1e-3 to 1e-8 below the day's (kSmallestComparedValue would skip all
// of it): each about 1e-3 of the band's zenith sky seen from the ground
// (docs/MEASUREMENTS.md, deep twilight), so what is left out is what a
// renderer could not show beside the rest of that sky.
inline constexpr double kSmallestComparedNauticalValue = 1e-9;
inline constexpr double kSmallestComparedAstronomicalValue = 1e-11;
// The floor for a sun band (night counts as astronomical twilight).
double smallestComparedValue(SunBand band);

// A query set's cameras are reported in at most this many altitude groups:
// one per distinct altitude (the standard set has 6), or for a set of more
// altitudes (a CSV's) neighbouring altitudes together, so that the table
// stays readable.
inline constexpr int kMaxCameraAltitudeGroups = 12;

// Camera altitudes reported together, m (min == max for one altitude).
struct CameraAltitudeGroup {
  double min_m = 0.0, max_m = 0.0;
  bool operator==(const CameraAltitudeGroup&) const = default;
  std::string label() const;  // "30 km", "0 to 2 km"
};

// The altitude groups of a query set's cameras (radiance and irradiance
// queries), lowest first.
std::vector<CameraAltitudeGroup> cameraAltitudeGroups(const QuerySet& queries);
// The group holding `altitude_m` (one of the set's camera altitudes).
size_t cameraAltitudeGroupOf(const std::vector<CameraAltitudeGroup>& groups, double altitude_m);

struct ErrorStats {
  int count = 0;    // values compared (per channel)
  int skipped = 0;  // reference below the band's smallest compared value
  // Relative errors |L - Lref| / Lref: RMS, nearest-rank 95th percentile,
  // largest; mean: their signed mean (L - Lref) / Lref, the bias.
  double rms = 0.0, p95 = 0.0, max = 0.0, mean = 0.0;
  double reference_standard_error = 0.0;  // RMS of the reference's own relative standard error
};

struct ErrorRow {
  std::string quantity;  // sky_radiance, ground_radiance, radiance_to_point, transmittance, sky_irradiance
  std::string band;      // day, low_sun, twilight, nautical, astronomical, night, all
  std::optional<CameraAltitudeGroup> camera_altitude;  // empty: every camera
  std::vector<ErrorStats> channels;
};

// Collects relative errors and summarises them into rows.
class ErrorStatsBuilder {
 public:
  // One compared value: counted in the row of every camera and in its
  // camera-altitude group's (none for a quantity not split by altitude).
  void add(const std::string& quantity, const std::string& band, std::optional<size_t> altitude_group, int channel,
           double value, double reference, double reference_error, double smallest_compared);
  // Rows in a fixed order (quantity, then sun band); by_altitude: the
  // camera-altitude groups' rows, else the rows of every camera.
  std::vector<ErrorRow> rows(int channels, const std::vector<CameraAltitudeGroup>& groups, bool by_altitude) const;

 private:
  struct Samples {
    std::vector<double> signed_errors, reference_errors;  // (L - Lref) / Lref, stderr / Lref
    int skipped = 0;
  };
  static constexpr size_t kEveryCamera = static_cast<size_t>(-1);
  // (quantity, band, altitude group or kEveryCamera) -> channel -> samples
  std::map<std::tuple<std::string, std::string, size_t>, std::map<int, Samples>> samples_;
  static ErrorStats summarize(const Samples& s);
};

struct ErrorReport {
  std::string query_set;
  std::vector<double> wavelengths_nm;      // the bake's (a colour bake's: those it integrated)
  std::vector<std::string> channel_names;  // channelNames (bake_file.h): "680nm", ... or X, Y, Z
  int reference_paths = 0;
  // Reference values below this are left out (kSmallestComparedValue; for a
  // colour bake's X, Y, Z scaled to their units).
  double smallest_compared_value = kSmallestComparedValue;
  std::vector<ErrorRow> rows;           // every camera
  std::vector<ErrorRow> altitude_rows;  // the same per camera-altitude group (transmittance not split)

  const ErrorRow* find(const std::string& quantity, const std::string& band) const;
  nlohmann::ordered_json toJson() const;
  std::string table() const;  // human-readable, one row per quantity and band, then per altitude group
};

}  // namespace skybake
