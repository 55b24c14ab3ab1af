// Every sun angle on a bake of the whole domain: the lookups give finite,
// non-negative values for any sun and camera, the sky darkens continuously
// and monotonically as the sun sinks below the baked sun angles, down to the
// night floor, and `skybake lookup` refuses none of it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>

#include "batch_lookups.h"
#include "runtime/physics/night_sky.h"
#include "runtime/sky.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

const fs::path kBakeDir = SKYBAKE_TEST_BAKE_DIR;

const Sky& earth() {
  static const Sky sky = Sky::load(kBakeDir / "earth.exr");
  return sky;
}

glm::dvec3 direction(double zenith_deg, double azimuth_deg) {
  const double t = radiansFromDegrees(zenith_deg), p = radiansFromDegrees(azimuth_deg);
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

glm::dvec3 cameraAt(const Sky& sky, double altitude_m) {
  return {0.0, 0.0, sky.atmosphere().bottom_radius_m + altitude_m};
}

void expectValid(const RadianceAndTransmittance& v, const std::string& where) {
  for (int c = 0; c < 3; ++c) {
    ASSERT_TRUE(std::isfinite(v.radiance[c]) && v.radiance[c] >= 0.0f) << where << " radiance " << v.radiance[c];
    ASSERT_TRUE(std::isfinite(v.transmittance[c]) && v.transmittance[c] >= 0.0f && v.transmittance[c] <= 1.0f)
        << where << " transmittance " << v.transmittance[c];
  }
}

// Cameras from below the ground to far out in space.
const std::vector<double> kCameraAltitudes_m = {-100.0, 0.0, 10.0, 1000.0, 1e4, 3e4, 59900.0, 1e5, 1e6, 1e7};

TEST(NightSky, EverySunAndCameraGivesFiniteNonNegativeValues) {
  const Sky& sky = earth();
  for (double sun_zenith = 0.0; sun_zenith <= 180.0; sun_zenith += 1.0) {
    const glm::dvec3 sun = direction(sun_zenith, 0.0);
    for (double altitude : kCameraAltitudes_m) {
      const glm::dvec3 camera = cameraAt(sky, altitude);
      std::vector<glm::dvec3> views;
      for (double view_zenith = 0.0; view_zenith <= 180.0; view_zenith += 15.0) {
        for (double azimuth : {0.0, 90.0, 180.0}) {
          const glm::dvec3 view = direction(view_zenith, azimuth);
          views.push_back(view);
          const std::string where =
              fmt::format("sun {} deg, camera {} m, view {} deg az {}", sun_zenith, altitude, view_zenith, azimuth);
          expectValid(sky.skyRadiance(camera, view, sun), where);
          expectValid(sky.receivedRadiance(camera, view, sun), where + " received");
          expectValid(sky.radianceToPoint(camera, camera + view * 5000.0, sun), where + " to a point 5 km away");
          expectValid(sky.radianceToPoint(camera, camera + view * 50000.0, sun), where + " to a point 50 km away");
        }
      }
      for (const test::BatchLookup& l : test::lookUpBatch(sky, camera, sun, views)) {
        expectValid(l.value, fmt::format("batch: sun {} deg, camera {} m", sun_zenith, altitude));
      }
      const SunAndSkyIrradiance e = sky.irradiance(camera, {0.0, 0.0, 1.0}, sun);
      for (int c = 0; c < 3; ++c) {
        ASSERT_TRUE(std::isfinite(e.sky[c]) && e.sky[c] >= 0.0f) << sun_zenith << " deg, " << altitude << " m";
        ASSERT_TRUE(std::isfinite(e.sun[c]) && e.sun[c] >= 0.0f) << sun_zenith << " deg, " << altitude << " m";
      }
    }
  }
}

TEST(NightSky, EverySunIsInsideTheRangesOfAWholeDomainBake) {
  const BakedRanges& ranges = earth().bakedRanges();
  for (double sun_zenith = 0.0; sun_zenith <= 180.0; sun_zenith += 0.5) {
    EXPECT_TRUE(ranges.containsSunZenith(sun_zenith)) << sun_zenith;
  }
  for (double altitude : kCameraAltitudes_m) EXPECT_TRUE(ranges.containsAltitude(altitude)) << altitude;
}

// The sky's brightness seen from inside the atmosphere, at one sun zenith
// angle: zenith radiance, horizon radiance toward, across and away from the
// sun, and the sky irradiance on a horizontal surface.
struct Brightness {
  static constexpr int kCount = 5;
  Spectrum value[kCount];
};
constexpr const char* kBrightnessNames[Brightness::kCount] = {"zenith radiance", "horizon radiance toward the sun",
                                                              "horizon radiance across", "horizon radiance away",
                                                              "sky irradiance"};

Brightness brightness(const Sky& sky, double altitude_m, double sun_zenith_deg) {
  const glm::dvec3 camera = cameraAt(sky, altitude_m);
  const glm::dvec3 sun = direction(sun_zenith_deg, 0.0);
  return {{sky.skyRadiance(camera, {0.0, 0.0, 1.0}, sun).radiance,
           sky.skyRadiance(camera, direction(90.0, 0.0), sun).radiance,
           sky.skyRadiance(camera, direction(90.0, 90.0), sun).radiance,
           sky.skyRadiance(camera, direction(90.0, 180.0), sun).radiance,
           sky.irradiance(camera, {0.0, 0.0, 1.0}, sun).sky}};
}

// Sun zenith angles from the horizon to the nadir: 0.01 deg steps within a
// degree of the lowest baked sun, where the tables end and the night
// continuation takes over, 0.1 deg elsewhere.
std::vector<double> sinkingSuns(double edge_deg) {
  std::vector<double> suns;
  for (int i = 0; 90.0 + 0.1 * i <= edge_deg - 1.0; ++i) suns.push_back(90.0 + 0.1 * i);
  for (int i = -100; i <= 100; ++i) suns.push_back(edge_deg + 0.01 * i);
  for (int i = 0; edge_deg + 1.1 + 0.1 * i <= 180.0; ++i) suns.push_back(edge_deg + 1.1 + 0.1 * i);
  suns.push_back(180.0);
  return suns;
}

// Altitudes of cameras inside the atmosphere (below the top, 60 km).
const std::vector<double> kInsideAltitudes_m = {-100.0, 0.0, 1000.0, 1e4, 3e4, 59000.0};

// Where the sky gets brighter as the sun sinks by less than this share of its
// value, the difference is float rounding of a sum of a few hundred terms
// (float epsilon 1.2e-7 each), not physics: 1e-5 leaves a margin of ten.
constexpr float kRoundingShare = 1e-5f;
// And a difference below this, W m^-2 (sr^-1) nm^-1, is float rounding of
// values far below anything a camera sees (the sky at night is 1e-9 and less
// by the time values this small arise).
constexpr float kRoundingFloor = 1e-30f;

TEST(NightSky, SkyDarkensMonotonicallyAsTheSunSinks) {
  const Sky& sky = earth();
  const double edge = sky.atmosphere().sun_max_zenith_deg;
  const std::vector<double> suns = sinkingSuns(edge);
  for (double altitude : kInsideAltitudes_m) {
    Brightness previous = brightness(sky, altitude, suns[0]);
    for (size_t i = 1; i < suns.size(); ++i) {
      const Brightness b = brightness(sky, altitude, suns[i]);
      for (int q = 0; q < Brightness::kCount; ++q) {
        for (int c = 0; c < 3; ++c) {
          ASSERT_LE(b.value[q][c], previous.value[q][c] * (1.0f + kRoundingShare) + kRoundingFloor)
              << kBrightnessNames[q] << ", channel " << c << ", camera " << altitude << " m, sun " << suns[i - 1]
              << " -> " << suns[i] << " deg";
        }
      }
      previous = b;
    }
  }
}

// Near the lowest baked sun the sky falls smoothly: the step across it is no
// larger than this many times the largest step on either side within 0.05
// deg (0.01 deg steps). The tables' own steps there vary by less than a
// factor 2 between neighbours (their interpolation is smooth within a
// texel); a clamp to the last baked angle (no step after it) or a drop to 0
// (a step of the whole value) fails.
constexpr float kEdgeStepRatio = 3.0f;

TEST(NightSky, NoStepAtTheLowestBakedSun) {
  const Sky& sky = earth();
  const double edge = sky.atmosphere().sun_max_zenith_deg;
  constexpr double kStep_deg = 0.01;
  for (double altitude : kInsideAltitudes_m) {
    std::vector<Brightness> b;
    for (int i = -5; i <= 5; ++i) b.push_back(brightness(sky, altitude, edge + kStep_deg * (i - 0.5)));
    // b[5] is 0.005 deg above the edge, b[6] 0.005 below: their step crosses it.
    for (int q = 0; q < Brightness::kCount; ++q) {
      for (int c = 0; c < 3; ++c) {
        auto step = [&](int i) { return b[i].value[q][c] - b[i + 1].value[q][c]; };
        float above = 0.0f, below = 0.0f;
        for (int i = 0; i < 5; ++i) above = std::max(above, step(i));
        for (int i = 6; i < 10; ++i) below = std::max(below, step(i));
        const std::string where = fmt::format("{}, channel {}, camera {} m: steps above {}, across {}, below {}",
                                              kBrightnessNames[q], c, altitude, above, step(5), below);
        EXPECT_LE(step(5), kEdgeStepRatio * std::max(above, below) + kRoundingFloor) << where;
        // The continuation goes on falling: a clamp would leave no step below.
        if (b[5].value[q][c] > 0.0f) {
          EXPECT_GT(below, 0.0f) << where;
        }
      }
    }
  }
}

// Through civil, nautical and astronomical twilight and on into the night
// (sun zenith 90 to 120 deg in 0.01 deg steps, across the lowest baked sun
// at 111 deg and the switch to the night continuation there), at several
// views and cameras and every wavelength, no step in the sky: the change
// from one 0.01 deg step to the next is at most kNeighbourStepRatio times
// the larger change of the two steps beside it, plus float rounding. For a
// smooth sky neighbouring changes differ by the share their slope changes
// over 0.01 deg (a few percent, less than 2x even at the mu_s texels' kinks;
// at a turning point the middle change is the smallest of the three); a
// jump adds its whole size to one change alone and fails once it exceeds
// twice the local change. The zenith and the horizon only darken as the
// sun sinks (the lit air recedes from them; multiple scattering only falls).
constexpr float kNeighbourStepRatio = 3.0f;

TEST(NightSky, NoStepThroughTheTwilightsAndIntoTheNight) {
  const Sky& sky = earth();
  constexpr double kFirstSun_deg = 90.0, kStep_deg = 0.01;
  constexpr int kSteps = 3000;  // to 120 deg
  struct View {
    double zenith_deg, azimuth_deg;
    bool darkens;  // physics says non-increasing as the sun sinks
  };
  const std::vector<View> views = {{0.0, 0.0, true},    {90.0, 0.0, true},  {90.0, 90.0, true},
                                   {90.0, 180.0, true}, {60.0, 0.0, false}, {60.0, 180.0, false}};
  double worst_ratio = 0.0;
  for (double altitude : {0.0, 1e4, 3e4}) {
    const glm::dvec3 camera = cameraAt(sky, altitude);
    for (const View& v : views) {
      const glm::dvec3 view = direction(v.zenith_deg, v.azimuth_deg);
      std::vector<Spectrum> sky_by_sun;
      for (int i = 0; i <= kSteps; ++i) {
        sky_by_sun.push_back(sky.skyRadiance(camera, view, direction(kFirstSun_deg + kStep_deg * i, 0.0)).radiance);
      }
      for (int c = 0; c < 3; ++c) {
        auto change = [&](int i) { return std::abs(sky_by_sun[i + 1][c] - sky_by_sun[i][c]); };
        for (int i = 1; i + 1 < kSteps; ++i) {
          const float beside = std::max(change(i - 1), change(i + 1));
          const float rounding = kRoundingShare * sky_by_sun[i][c] + kRoundingFloor;
          const std::string where = fmt::format(
              "camera {} m, view {} deg azimuth {}, channel {}, sun {:.2f} -> {:.2f} deg", altitude, v.zenith_deg,
              v.azimuth_deg, c, kFirstSun_deg + kStep_deg * i, kFirstSun_deg + kStep_deg * (i + 1));
          ASSERT_LE(change(i), kNeighbourStepRatio * beside + rounding)
              << where << ": changes " << change(i - 1) << ", " << change(i) << ", " << change(i + 1);
          if (beside > rounding) worst_ratio = std::max(worst_ratio, double(change(i) / beside));
          if (v.darkens) {
            ASSERT_LE(sky_by_sun[i + 1][c], sky_by_sun[i][c] * (1.0f + kRoundingShare) + kRoundingFloor) << where;
          }
        }
      }
    }
  }
  RecordProperty("worst_neighbour_step_ratio", std::to_string(worst_ratio));
}

TEST(NightSky, SunAtTheNadirGivesTheNightFloor) {
  const Sky& sky = earth();
  for (double altitude : kInsideAltitudes_m) {
    const Brightness b = brightness(sky, altitude, 180.0);
    for (int q = 0; q < Brightness::kCount; ++q) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(b.value[q][c], static_cast<float>(kNightFloor)) << kBrightnessNames[q] << ", " << altitude << " m";
      }
    }
  }
}

// Below the baked suns the tables' part is scaled down, never up, and is
// gone well before the nadir.
TEST(NightSky, ContinuationFallsFromOneToZero) {
  const Sky& sky = earth();
  const NightContinuation& night = sky.sampler().night();
  const double edge_mu_s = std::cos(radiansFromDegrees(sky.atmosphere().sun_max_zenith_deg));
  Spectrum previous(1.0f);
  for (double zenith = sky.atmosphere().sun_max_zenith_deg; zenith <= 180.0; zenith += 0.05) {
    const Spectrum f = night.scale(std::min(std::cos(radiansFromDegrees(zenith)), edge_mu_s));
    for (int c = 0; c < 3; ++c) {
      ASSERT_LE(f[c], previous[c]) << zenith;
      ASSERT_GE(f[c], 0.0f) << zenith;
    }
    previous = f;
  }
  for (int c = 0; c < 3; ++c) EXPECT_EQ(night.scale(-1.0)[c], 0.0f);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(night.scale(edge_mu_s)[c], 1.0f);
}

// The batch path scales its (r, mu_s) slices as the scalar lookups scale
// each table read: the same values below the baked suns too.
TEST(NightSky, BatchLookupsEqualScalarLookupsBelowTheBakedSuns) {
  const Sky& sky = earth();
  for (double sun_zenith : {105.0, 110.0, 115.0}) {
    for (double altitude : {0.0, 3e4}) {
      const glm::dvec3 camera = cameraAt(sky, altitude), sun = direction(sun_zenith, 10.0);
      for (const test::BatchLookup& l : test::lookUpBatch(sky, camera, sun, test::batchTestViews(direction))) {
        const RadianceAndTransmittance v = sky.skyRadiance(camera, l.view, sun);
        for (int c = 0; c < 3; ++c) {
          // As Sky.BatchLookupsEqualScalarLookups: float rounding, 1e-5, of
          // values that are all far below 1e-10 here, hence no absolute slack
          // beyond float's smallest normal numbers.
          EXPECT_NEAR(l.value.radiance[c], v.radiance[c], 1e-5f * v.radiance[c] + 1e-37f)
              << "sun " << sun_zenith << ", camera " << altitude << " m";
        }
      }
    }
  }
}

// `skybake lookup` on a bake of the whole domain: every sun from the zenith
// to the nadir and cameras below the ground and in space, none refused.
TEST(NightSky, LookupRefusesNoSunNorCameraOfAWholeDomainBake) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("skybake_night_{}", ::getpid());
  fs::create_directories(dir);
  std::ofstream radiance(dir / "radiance.csv"), irradiance(dir / "irradiance.csv");
  radiance << "altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg\n";
  irradiance << "altitude_m,sun_zenith_deg\n";
  int rows = 0;
  for (double sun = 0.0; sun <= 180.0; sun += 2.5) {
    for (double altitude : kCameraAltitudes_m) {
      for (double view : {0.0, 90.0, 120.0}) radiance << fmt::format("{},{},{},0\n", altitude, sun, view), ++rows;
      irradiance << fmt::format("{},{}\n", altitude, sun);
    }
  }
  radiance.close();
  irradiance.close();
  const std::string bake = (kBakeDir / "earth.exr").string();
  for (const char* kind : {"radiance", "irradiance"}) {
    const std::string command =
        fmt::format("'{}' lookup {} '{}' --queries '{}/{}.csv' -o '{}/{}_out.csv' 2>'{}/stderr'", SKYBAKE_BINARY, kind,
                    bake, dir.string(), kind, dir.string(), kind, dir.string());
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    std::ifstream out(dir / fmt::format("{}_out.csv", kind));
    int lines = 0;
    for (std::string line; std::getline(out, line);) ++lines;
    EXPECT_EQ(lines - 1, std::string(kind) == "radiance" ? rows : rows / 3) << kind;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace skybake
