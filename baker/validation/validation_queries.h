// The queries `skybake validate` and `skybake compare` evaluate: the standard
// set (docs/QUERIES.md) or the user's CSV.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace skybake {

struct RadianceQuery {
  double altitude_m;
  double sun_zenith_deg;
  double view_zenith_deg;
  double view_azimuth_deg;  // from the sun's azimuth
  double distance_m;        // > 0: radiance to the point at this distance
};

struct IrradianceQuery {
  double altitude_m;
  double sun_zenith_deg;
};

struct QuerySet {
  std::string name;
  std::vector<RadianceQuery> radiance;
  std::vector<IrradianceQuery> irradiance;
};

// The standard set for an atmosphere with the given top altitude (m above
// the ground): cameras at 0, 1 km, 10 km, 30 km, just under the top and in
// space; suns from the zenith to 10 deg below the horizon; views over the
// dome and the ground, denser near the horizon; azimuths 0, 90 and 180 deg.
QuerySet standardQuerySet(double atmosphere_thickness_m);

// A small subset of the standard set (for CI and quick looks).
QuerySet quickQuerySet(double atmosphere_thickness_m);

// Radiance queries from a CSV with the columns of `skybake lookup radiance`.
QuerySet querySetFromCsv(const std::filesystem::path& path);

// "standard", "quick", or else the path of a CSV (the --queries option).
QuerySet querySetNamed(const std::string& which, double atmosphere_thickness_m);

// Sun bands: day (elevation > 10 deg), low sun (0 to 10), twilight (-10 to 0).
enum class SunBand { Day, LowSun, Twilight, Night };
SunBand sunBand(double sun_zenith_deg);
const char* sunBandName(SunBand band);

}  // namespace skybake
