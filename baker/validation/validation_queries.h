// The queries `skybake validate` and `skybake compare` evaluate: the standard
// set (docs/QUERIES.md) or the user's CSV.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace skybake {

class CsvReader;
struct CsvRow;

// Limits on a query's numbers, shared by the query CSVs and render's camera.
// Altitudes below the ground are allowed (treated as on it, like the
// runtime); beyond 1e12 m (seven astronomical units) an altitude or distance
// is surely a unit mistake.
inline constexpr double kMaxQueryAltitude_m = 1e12;
inline constexpr double kMaxQueryDistance_m = 1e12;
// Zenith angles lie in [0, 180] degrees; azimuths within one turn either way.
inline constexpr double kMaxZenithAngle_deg = 180.0;
inline constexpr double kMaxAzimuth_deg = 360.0;
// A query's point (radiance to a point) this close below the ground counts
// as on it: its altitude comes from the camera, direction and distance
// through a square root, which rounds by far less. Points further below are
// inside the planet: skybake lookup refuses them and validate leaves them
// out, though the camera of a query may be below the ground (looked up on it).
inline constexpr double kPointOnGroundTolerance_m = 1e-3;

// A moon before the sun (a solar eclipse), as the camera sees it: its
// centre `separation_deg` from the sun's, turned from it across the sun's
// vertical plane (toward +y of the query's local frame, perpendicular to the
// sun), at the mean lunar distance (runtime/physics/moon_occluder.h). Angular radius
// 0: no moon.
struct MoonQuery {
  double separation_deg = 0.0;
  double angular_radius_deg = 0.0;
  bool present() const { return angular_radius_deg > 0.0; }
};
// A moon's angular radius above this (deg) is no moon's: the Moon spans 0.24
// to 0.28 deg from the Earth; 5 deg leaves room for other worlds' moons.
inline constexpr double kMaxMoonAngularRadius_deg = 5.0;

struct RadianceQuery {
  double altitude_m;
  double sun_zenith_deg;
  double view_zenith_deg;
  double view_azimuth_deg;  // from the sun's azimuth
  double distance_m;        // > 0: radiance to the point at this distance
  MoonQuery moon{};         // none but in eclipse queries
};

// Sky irradiance on a horizontal surface above the +z pole.
struct IrradianceQuery {
  double altitude_m;
  double sun_zenith_deg;
  MoonQuery moon{};  // none but in eclipse queries
};

struct QuerySet {
  std::string name;
  std::vector<RadianceQuery> radiance;
  std::vector<IrradianceQuery> irradiance;
};

// The standard set for an atmosphere between these radii (m from the
// planet's centre): cameras at 0, 1 km, 10 km, 30 km, just under the top and
// in space; suns from the zenith to 18 deg below the horizon; views over the
// dome and the ground, denser near the horizon; azimuths 0, 90 and 180 deg.
// The suns of the first set (zenith to 10 deg below the horizon) come first
// and keep their order; the deep-twilight suns (to 18 deg below) follow.
// The sky irradiance is asked for at every camera inside the atmosphere and
// at the altitudes where its table is weakest (kWeakIrradianceAltitudes),
// at every sun and across each altitude's own sunset.
QuerySet standardQuerySet(double bottom_radius_m, double top_radius_m);

// A small subset of the standard set (for CI and quick looks).
QuerySet quickQuerySet(double atmosphere_thickness_m);

// Solar eclipses (docs/QUERIES.md): the sun 40 deg high, a moon making a
// total eclipse seen from the umbra's centre, from inside it off centre and
// from just outside it, partial eclipses and an annular one; cameras on the
// ground and at 10 km; views at the zenith, across the sky, near the
// horizon and to the ground; rays to points; and the sky irradiance on the
// ground and at 10 km under every moon.
QuerySet eclipseQuerySet();

// The columns of a radiance query CSV (those of `skybake lookup radiance`),
// each value checked against the limits above. Throws Error(BadInput) with
// the file, line and column of a missing column or an out-of-range value.
struct RadianceQueryColumns {
  size_t altitude_m;
  size_t sun_zenith_deg;
  size_t view_zenith_deg;
  size_t view_azimuth_deg;
  std::optional<size_t> distance_m;
  std::optional<size_t> moon_separation_deg;  // the eclipse columns (MoonQuery)
  std::optional<size_t> moon_angular_radius_deg;
};
// The columns of a radiance query CSV (required ones refused when missing;
// an empty cell of an optional one means what leaving it out means).
RadianceQueryColumns radianceQueryColumns(CsvReader& reader);
// Refuses a row whose numbers lie outside the query limits above.
void requireRadianceQueryRanges(const CsvReader& reader, const CsvRow& row, const RadianceQueryColumns& columns);

// Radiance queries from a CSV with the columns of `skybake lookup radiance`,
// or sky irradiance queries from one with those of `skybake lookup
// irradiance` alone (altitude_m and sun_zenith_deg, no view columns).
QuerySet querySetFromCsv(const std::filesystem::path& path);

// "standard", "quick", "eclipse", or else the path of a CSV (the --queries option).
QuerySet querySetNamed(const std::string& which, double bottom_radius_m, double top_radius_m);

// Sun bands by the sun's zenith angle: day (elevation above 10 deg), low sun
// (0 to 10 deg), then the three twilights as almanacs define them by the
// sun's depression below the horizon: civil ("twilight", 0 to 6 deg),
// nautical (6 to 12) and astronomical (12 to 18); night beyond. Each band
// holds its upper zenith end (a sun on the horizon is low sun).
inline constexpr double kLowSunFromZenith_deg = 80.0;
inline constexpr double kHorizonZenith_deg = 90.0;
inline constexpr double kCivilTwilightEndZenith_deg = 96.0;
inline constexpr double kNauticalTwilightEndZenith_deg = 102.0;
inline constexpr double kAstronomicalTwilightEndZenith_deg = 108.0;
enum class SunBand { Day, LowSun, Twilight, Nautical, Astronomical, Night };
SunBand sunBand(double sun_zenith_deg);
const char* sunBandName(SunBand band);
// Every band, from day to night (the order reports list them in).
const std::vector<SunBand>& allSunBands();

}  // namespace skybake
