#include "baker/validation/error_report.h"

#include <gtest/gtest.h>

#include <cmath>

namespace skybake {
namespace {

TEST(CameraAltitudeGroups, TheStandardSetHasAGroupPerCameraAltitude) {
  const QuerySet standard = standardQuerySet(6360e3, 6420e3);
  const std::vector<CameraAltitudeGroup> groups = cameraAltitudeGroups(standard);
  // The cameras' altitudes and those where only the sky irradiance is asked for.
  ASSERT_EQ(groups.size(), 9u);
  const std::vector<std::string> labels = {"0 km",  "1 km",  "2 km",    "10 km", "30 km",
                                           "44 km", "54 km", "59.9 km", "160 km"};
  for (size_t g = 0; g < groups.size(); ++g) {
    EXPECT_EQ(groups[g].min_m, groups[g].max_m);
    EXPECT_EQ(groups[g].label(), labels[g]);
  }
  EXPECT_EQ(cameraAltitudeGroupOf(groups, 30000.0), 4u);
}

TEST(CameraAltitudeGroups, ManyAltitudesShareGroupsInOrder) {
  QuerySet set;
  for (int i = 0; i < 30; ++i) set.radiance.push_back({1000.0 * i, 30.0, 0.0, 0.0, 0.0});
  set.irradiance.push_back({500.0, 30.0});  // irradiance cameras count too
  const std::vector<CameraAltitudeGroup> groups = cameraAltitudeGroups(set);
  ASSERT_EQ(groups.size(), static_cast<size_t>(kMaxCameraAltitudeGroups));
  EXPECT_EQ(groups.front().min_m, 0.0);
  EXPECT_EQ(groups.back().max_m, 29000.0);
  for (size_t g = 1; g < groups.size(); ++g) EXPECT_GT(groups[g].min_m, groups[g - 1].max_m) << g;
  // 31 altitudes in 12 groups: 2 or 3 each, every altitude in exactly one.
  for (double altitude : {0.0, 500.0, 14000.0, 29000.0}) {
    const CameraAltitudeGroup& g = groups[cameraAltitudeGroupOf(groups, altitude)];
    EXPECT_LE(g.min_m, altitude);
    EXPECT_GE(g.max_m, altitude);
  }
  EXPECT_EQ(groups.front().label(), "0 to 0.5 km");
}

TEST(ErrorStatsBuilder, AltitudeGroupsShowTheBiasTheAverageHides) {
  const std::vector<CameraAltitudeGroup> groups = {{0.0, 0.0}, {30000.0, 30000.0}};
  ErrorStatsBuilder stats;
  constexpr double kFloor = 1e-5;
  // Ground cameras 1 % low, high cameras 1 % and 3 % high.
  stats.add("sky_radiance", "day", 0, 0, 0.99, 1.0, 0.001, kFloor);
  stats.add("sky_radiance", "day", 0, 0, 1.98, 2.0, 0.001, kFloor);
  stats.add("sky_radiance", "day", 1, 0, 1.01, 1.0, 0.001, kFloor);
  stats.add("sky_radiance", "day", 1, 0, 1.03, 1.0, 0.001, kFloor);
  stats.add("sky_radiance", "day", 1, 0, 1.0, 1e-6, 0.0, kFloor);  // below the floor: skipped
  stats.add("transmittance", "all", std::nullopt, 0, 0.5, 0.5, 0.0, kFloor);
  const std::vector<ErrorRow> every = stats.rows(1, groups, false);
  const std::vector<ErrorRow> by_altitude = stats.rows(1, groups, true);
  ASSERT_EQ(every.size(), 2u);        // sky radiance, transmittance
  ASSERT_EQ(by_altitude.size(), 2u);  // sky radiance at each altitude; transmittance is not split
  const ErrorStats& all = every[0].channels[0];
  EXPECT_FALSE(every[0].camera_altitude.has_value());
  EXPECT_EQ(all.count, 4);
  EXPECT_EQ(all.skipped, 1);
  // Relative errors -1, -1, +1, +3 %: mean +0.5 %, RMS sqrt(3) %. Double
  // arithmetic on these values is exact to 1e-15.
  EXPECT_NEAR(all.mean, 0.005, 1e-12);
  EXPECT_NEAR(all.rms, std::sqrt(3.0) * 0.01, 1e-12);
  EXPECT_EQ(*by_altitude[0].camera_altitude, groups[0]);
  EXPECT_NEAR(by_altitude[0].channels[0].mean, -0.01, 1e-12);
  EXPECT_EQ(by_altitude[0].channels[0].count, 2);
  EXPECT_EQ(*by_altitude[1].camera_altitude, groups[1]);
  EXPECT_NEAR(by_altitude[1].channels[0].mean, 0.02, 1e-12);
  EXPECT_EQ(by_altitude[1].channels[0].skipped, 1);
}

TEST(ErrorReport, TableAndJsonCarryTheAltitudeRows) {
  const std::vector<CameraAltitudeGroup> groups = {{0.0, 0.0}, {30000.0, 30000.0}};
  ErrorStatsBuilder stats;
  stats.add("sky_radiance", "day", 0, 0, 0.99, 1.0, 0.001, kSmallestComparedValue);
  stats.add("sky_radiance", "day", 1, 0, 1.01, 1.0, 0.001, kSmallestComparedValue);
  ErrorReport report;
  report.channel_names = {"680nm"};
  report.wavelengths_nm = {680.0};
  report.rows = stats.rows(1, groups, false);
  report.altitude_rows = stats.rows(1, groups, true);
  const std::string table = report.table();
  EXPECT_NE(table.find("by camera altitude"), std::string::npos) << table;
  EXPECT_NE(table.find("30 km"), std::string::npos) << table;
  EXPECT_NE(table.find("1.00 / +1.00"), std::string::npos) << table;
  EXPECT_NE(table.find("1.00 / -1.00"), std::string::npos) << table;
  const nlohmann::ordered_json j = report.toJson();
  ASSERT_EQ(j["errors_by_camera_altitude"].size(), 2u);
  EXPECT_EQ(j["errors_by_camera_altitude"][1]["camera_altitude_m"][0], 30000.0);
  EXPECT_NEAR(j["errors_by_camera_altitude"][1]["channels"][0]["mean"].get<double>(), 0.01, 1e-12);
  EXPECT_NEAR(j["errors"][0]["channels"][0]["mean"].get<double>(), 0.0, 1e-12);
}

}  // namespace
}  // namespace skybake
