#include "baker/validation/validation_queries.h"

#include <cmath>

#include "data_formats/angles.h"
#include "data_formats/parameterization/ray_sphere.h"
#include "data_formats/queries/csv_table.h"

namespace skybake {
namespace {

// Below the top by this much: "just under the top" without sitting on it.
constexpr double kJustUnderTop_m = 100.0;
// Far enough out that the whole atmosphere is below the horizon's limb.
constexpr double kSpaceAltitudeAboveTop_m = 100000.0;
// Where the sky irradiance table is weakest, besides the set's cameras: 2 km
// up, inside the aerosol layer (a 1.2 km scale height for the Earth's)
// between two rows; and at 44/60 and 0.9 of the thickness (44 and 54 km for
// the Earth), where the sky above thins to nothing toward the top and each
// altitude's own sunset comes later than a lower row's. The first in m, the
// others as shares of the thickness.
constexpr double kWeakIrradianceAltitudes[] = {2000.0, 44.0 / 60.0, 0.9};
// Suns after each altitude's own sunset (deg beyond the sun on its
// horizon), and one before it: there the sky's light falls steepest.
constexpr double kAfterOwnSunset_deg[] = {-0.5, 0.25, 1.0};

QuerySet makeSet(const std::string& name, const std::vector<double>& altitudes, const std::vector<double>& suns,
                 const std::vector<double>& views, const std::vector<double>& space_views,
                 const std::vector<double>& azimuths, double thickness, bool with_points) {
  QuerySet set;
  set.name = name;
  for (double altitude : altitudes) {
    const bool in_space = altitude > thickness;
    for (double sun : suns) {
      for (double view : in_space ? space_views : views) {
        for (double azimuth : azimuths) {
          set.radiance.push_back({altitude, sun, view, azimuth, 0.0});
        }
      }
      if (!in_space) set.irradiance.push_back({altitude, sun});
    }
  }
  if (with_points) {
    // Aerial perspective: points 1, 10 and 50 km away near the horizontal.
    for (double altitude : {altitudes[0], altitudes[1]}) {
      for (double sun : suns) {
        for (double distance : {1000.0, 10000.0, 50000.0}) {
          for (double view : {80.0, 89.0}) set.radiance.push_back({altitude, sun, view, 90.0, distance});
        }
      }
    }
  }
  return set;
}

}  // namespace

QuerySet standardQuerySet(double bottom_radius_m, double top_radius_m) {
  const double thickness = top_radius_m - bottom_radius_m;
  const std::vector<double> cameras = {
      0.0, 1000.0, 10000.0, 30000.0, thickness - kJustUnderTop_m, thickness + kSpaceAltitudeAboveTop_m};
  const std::vector<double> suns = {0.0,  30.0,  60.0, 75.0,  85.0,  88.0,  90.0, 92.0,
                                    95.0, 100.0, 98.0, 102.0, 104.0, 106.0, 108.0};
  QuerySet set =
      makeSet("standard", cameras, suns, {0.0, 30.0, 60.0, 75.0, 84.0, 88.0, 89.5, 90.5, 92.0, 96.0, 120.0, 170.0},
              {100.0, 106.0, 110.0, 120.0, 150.0, 180.0}, {0.0, 90.0, 180.0}, thickness, true);
  // makeSet asked for the irradiance at every camera inside the atmosphere.
  std::vector<double> irradiance_altitudes;
  for (double altitude : cameras) {
    if (altitude <= thickness) irradiance_altitudes.push_back(altitude);
  }
  for (double altitude : {kWeakIrradianceAltitudes[0], kWeakIrradianceAltitudes[1] * thickness,
                          kWeakIrradianceAltitudes[2] * thickness}) {
    for (double sun : suns) set.irradiance.push_back({altitude, sun});
    irradiance_altitudes.push_back(altitude);
  }
  for (double altitude : irradiance_altitudes) {
    // The sun on this altitude's own horizon, below the ground's.
    const double sunset_deg =
        degreesFromRadians(std::acos(tangentZenithCosine(bottom_radius_m + altitude, bottom_radius_m)));
    for (double after_deg : kAfterOwnSunset_deg) set.irradiance.push_back({altitude, sunset_deg + after_deg});
  }
  return set;
}

QuerySet quickQuerySet(double thickness) {
  return makeSet("quick", {0.0, 10000.0}, {30.0, 85.0, 95.0}, {0.0, 60.0, 88.0, 120.0}, {}, {0.0, 180.0}, thickness,
                 false);
}

QuerySet eclipseQuerySet() {
  // Sun 40 deg high. The moon's angular radius 0.28 deg against the sun's
  // 0.2666 (Earth) casts an umbra about 90 km across; 0.006 deg from the
  // centre puts the camera 40 km off its axis, 0.03 deg 200 km off, outside
  // it; 0.25 and 0.45 deg are partial eclipses of three quarters and a
  // quarter of the disk; 0.25 deg centred is annular.
  const double sun_zenith_deg = 50.0;
  const MoonQuery moons[] = {{0.0, 0.28}, {0.006, 0.28}, {0.03, 0.28}, {0.25, 0.28}, {0.45, 0.28}, {0.0, 0.25}};
  const double views[][2] = {{0.0, 0.0},  {45.0, 0.0},   {60.0, 180.0}, {60.0, 90.0},
                             {85.0, 0.0}, {88.0, 180.0}, {89.5, 90.0},  {120.0, 90.0}};
  // Rays to points (aerial perspective) under every moon but the second
  // partial one, whose shadow the first one's already follows: 5 and 50 km
  // toward the sun, 20 and 120 km across it near the horizontal (view
  // zenith, azimuth from the sun's, distance in m). Four per camera and
  // moon keep the set's reference to about 1.4 times the sky's alone.
  const MoonQuery point_moons[] = {moons[0], moons[1], moons[2], moons[3], moons[5]};
  const double points[][3] = {{85.0, 0.0, 5000.0}, {85.0, 0.0, 50000.0}, {89.0, 90.0, 20000.0}, {89.0, 90.0, 120000.0}};
  QuerySet set;
  set.name = "eclipse";
  for (double altitude : {0.0, 10000.0}) {
    for (const MoonQuery& moon : moons) {
      for (const auto& view : views) set.radiance.push_back({altitude, sun_zenith_deg, view[0], view[1], 0.0, moon});
    }
  }
  for (double altitude : {0.0, 10000.0}) {
    for (const MoonQuery& moon : point_moons) {
      for (const auto& p : points) set.radiance.push_back({altitude, sun_zenith_deg, p[0], p[1], p[2], moon});
    }
  }
  // The light on the ground (and at 10 km) under each moon: in totality it
  // comes from the sunlit air beyond the umbra, from every direction.
  for (double altitude : {0.0, 10000.0}) {
    for (const MoonQuery& moon : moons) set.irradiance.push_back({altitude, sun_zenith_deg, moon});
  }
  return set;
}

RadianceQueryColumns radianceQueryColumns(CsvReader& q) {
  // The optional columns' empty cells mean what leaving the column out
  // means: no distance (a view ray), no moon.
  return {q.require("altitude_m"),
          q.require("sun_zenith_deg"),
          q.require("view_zenith_deg"),
          q.require("view_azimuth_deg"),
          q.findOptional("distance_m", 0.0),
          q.findOptional("moon_separation_deg", 0.0),
          q.findOptional("moon_angular_radius_deg", 0.0)};
}

void requireRadianceQueryRanges(const CsvReader& q, const CsvRow& row, const RadianceQueryColumns& c) {
  q.requireRange(row, c.altitude_m, -kMaxQueryAltitude_m, kMaxQueryAltitude_m);
  q.requireRange(row, c.sun_zenith_deg, 0.0, kMaxZenithAngle_deg);
  q.requireRange(row, c.view_zenith_deg, 0.0, kMaxZenithAngle_deg);
  q.requireRange(row, c.view_azimuth_deg, -kMaxAzimuth_deg, kMaxAzimuth_deg);
  if (c.distance_m) q.requireRange(row, *c.distance_m, -kMaxQueryDistance_m, kMaxQueryDistance_m);
  if (c.moon_separation_deg) q.requireRange(row, *c.moon_separation_deg, 0.0, kMaxZenithAngle_deg);
  if (c.moon_angular_radius_deg) q.requireRange(row, *c.moon_angular_radius_deg, 0.0, kMaxMoonAngularRadius_deg);
}

// A CSV with the columns of `lookup irradiance` alone (altitude_m,
// sun_zenith_deg; no view): sky irradiance on a horizontal surface.
QuerySet irradianceQuerySetFromCsv(CsvReader& q, const std::string& name) {
  const size_t altitude_m = q.require("altitude_m");
  const size_t sun_zenith_deg = q.require("sun_zenith_deg");
  QuerySet set;
  set.name = name;
  for (CsvRow row; q.next(row);) {
    q.requireRange(row, altitude_m, -kMaxQueryAltitude_m, kMaxQueryAltitude_m);
    q.requireRange(row, sun_zenith_deg, 0.0, kMaxZenithAngle_deg);
    set.irradiance.push_back({row.values[altitude_m], row.values[sun_zenith_deg]});
  }
  return set;
}

QuerySet querySetFromCsv(const std::filesystem::path& path) {
  CsvReader q(path);
  if (!q.find("view_zenith_deg") && !q.find("view_azimuth_deg")) {
    return irradianceQuerySetFromCsv(q, path.filename().string());
  }
  const RadianceQueryColumns c = radianceQueryColumns(q);
  QuerySet set;
  set.name = path.filename().string();
  for (CsvRow row; q.next(row);) {
    requireRadianceQueryRanges(q, row, c);
    const std::vector<double>& v = row.values;
    const MoonQuery moon{c.moon_separation_deg ? v[*c.moon_separation_deg] : 0.0,
                         c.moon_angular_radius_deg ? v[*c.moon_angular_radius_deg] : 0.0};
    const double distance_m = c.distance_m ? v[*c.distance_m] : 0.0;
    set.radiance.push_back(
        {v[c.altitude_m], v[c.sun_zenith_deg], v[c.view_zenith_deg], v[c.view_azimuth_deg], distance_m, moon});
  }
  return set;
}

QuerySet querySetNamed(const std::string& which, double bottom_radius_m, double top_radius_m) {
  if (which == "standard") return standardQuerySet(bottom_radius_m, top_radius_m);
  if (which == "quick") return quickQuerySet(top_radius_m - bottom_radius_m);
  if (which == "eclipse") return eclipseQuerySet();
  return querySetFromCsv(which);
}

SunBand sunBand(double sun_zenith_deg) {
  if (sun_zenith_deg < kLowSunFromZenith_deg) return SunBand::Day;
  if (sun_zenith_deg <= kHorizonZenith_deg) return SunBand::LowSun;
  if (sun_zenith_deg <= kCivilTwilightEndZenith_deg) return SunBand::Twilight;
  if (sun_zenith_deg <= kNauticalTwilightEndZenith_deg) return SunBand::Nautical;
  if (sun_zenith_deg <= kAstronomicalTwilightEndZenith_deg) return SunBand::Astronomical;
  return SunBand::Night;
}

const std::vector<SunBand>& allSunBands() {
  static const std::vector<SunBand> bands = {SunBand::Day,      SunBand::LowSun,       SunBand::Twilight,
                                             SunBand::Nautical, SunBand::Astronomical, SunBand::Night};
  return bands;
}

const char* sunBandName(SunBand band) {
  switch (band) {
    case SunBand::Day:
      return "day";
    case SunBand::LowSun:
      return "low_sun";
    case SunBand::Twilight:
      return "twilight";
    case SunBand::Nautical:
      return "nautical";
    case SunBand::Astronomical:
      return "astronomical";
    case SunBand::Night:
      return "night";
  }
  return "?";
}

}  // namespace skybake
