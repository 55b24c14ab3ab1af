// The geometry contract of every Sky lookup (runtime/lookup_geometry.h,
// runtime/README.md "Geometry"): random positions, directions and moons,
// non-finite, zero, huge, tiny and non-unit among them, give either
// Error(BadInput) for exactly the inputs the contract refuses, or finite
// results in their physical range; and what the contract normalises or
// clamps reads as its normal form.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "data_formats/error.h"
#include "runtime/lookup_geometry.h"
#include "runtime/sky.h"

namespace skybake {
namespace {

const std::filesystem::path kBakeDir = SKYBAKE_TEST_BAKE_DIR;

const Sky& earth() {
  static const Sky sky = Sky::load(kBakeDir / "earth.exr");
  return sky;
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// One component of a hostile vector: ordinary, huge, tiny, zero or non-finite.
double hostileComponent(std::mt19937_64& rng, double scale) {
  std::uniform_int_distribution<int> kind(0, 9);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  switch (kind(rng)) {
    case 0:
      return 0.0;
    case 1:
      return unit(rng) * 1e300;
    case 2:
      return unit(rng) * 1e-300;
    case 3:
      return kNaN;
    case 4:
      return unit(rng) < 0.0 ? -kInf : kInf;
    default:
      return unit(rng) * scale;
  }
}

glm::dvec3 hostileVector(std::mt19937_64& rng, double scale) {
  return {hostileComponent(rng, scale), hostileComponent(rng, scale), hostileComponent(rng, scale)};
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool refusedDirection(const glm::dvec3& v) { return !finite(v) || (v.x == 0.0 && v.y == 0.0 && v.z == 0.0); }

// Every lane of every result finite and >= 0, transmittances <= 1.
void expectPhysical(const Spectrum& value, bool transmittance, const char* what) {
  for (int c = 0; c < kMaxChannels; ++c) {
    ASSERT_TRUE(std::isfinite(value[c]) && value[c] >= 0.0f) << what << " lane " << c << " = " << value[c];
    if (transmittance) {
      ASSERT_LE(value[c], 1.0f) << what << " lane " << c;
    }
  }
}

// The same for a path's radiance and transmittance, and for irradiance.
void expectPhysical(const RadianceAndTransmittance& v, const std::string& what) {
  expectPhysical(v.radiance, false, (what + " radiance").c_str());
  expectPhysical(v.transmittance, true, (what + " transmittance").c_str());
}
void expectPhysical(const SunAndSkyIrradiance& e, const std::string& what) {
  expectPhysical(e.sun, false, (what + " sun").c_str());
  expectPhysical(e.sky, false, (what + " sky").c_str());
}

// Runs `lookup`; expects BadInput exactly when `refused`, otherwise no throw.
void expectContract(bool refused, const std::function<void()>& lookup, const char* what) {
  if (refused) {
    try {
      lookup();
      ADD_FAILURE() << what << ": a refused input was looked up";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::BadInput) << what << ": " << e.what();
    }
  } else {
    EXPECT_NO_THROW(lookup()) << what;
  }
}

TEST(LookupGeometry, HostileGeometryGivesBadInputOrPhysicalResultsInEveryLookup) {
  const Sky& sky = earth();
  const double R = sky.atmosphere().bottom_radius_m;
  std::mt19937_64 rng(20261206);
  // 400 draws of each lookup: about 1 s; every kind of component appears in
  // each argument dozens of times.
  for (int draw = 0; draw < 400; ++draw) {
    const glm::dvec3 camera = hostileVector(rng, 2.0 * R);
    const glm::dvec3 point = hostileVector(rng, 2.0 * R);
    const glm::dvec3 view = hostileVector(rng, 1.0);
    const glm::dvec3 sun = hostileVector(rng, 1.0);
    const glm::dvec3 normal = hostileVector(rng, 1.0);
    const double radius = hostileComponent(rng, 3e6);
    const Moon moon{hostileVector(rng, 4e8), radius};
    const bool bad_moon = !finite(moon.centre_m) || !(std::isfinite(radius) && radius >= 0.0);
    const bool bad_camera = !finite(camera), bad_point = !finite(point);
    SCOPED_TRACE(draw);

    expectContract(
        bad_camera || refusedDirection(view) || refusedDirection(sun),
        [&] {
          expectPhysical(sky.skyRadiance(camera, view, sun), "skyRadiance");
          const RadianceAndTransmittance received = sky.receivedRadiance(camera, view, sun);
          expectPhysical(received.radiance, false, "receivedRadiance");
        },
        "skyRadiance");
    expectContract(
        bad_camera || refusedDirection(view) || refusedDirection(sun) || bad_moon,
        [&] {
          expectPhysical(sky.skyRadiance(camera, view, {sun, moon}), "eclipse skyRadiance");
        },
        "eclipse skyRadiance");
    expectContract(
        bad_camera || bad_point || refusedDirection(sun),
        [&] {
          expectPhysical(sky.radianceToPoint(camera, point, sun), "radianceToPoint");
          expectPhysical(sky.transmittance(camera, point), true, "transmittance");
        },
        "radianceToPoint");
    expectContract(
        bad_point || refusedDirection(normal) || refusedDirection(sun),
        [&] { expectPhysical(sky.irradiance(point, normal, sun), "irradiance"); }, "irradiance");
    expectContract(
        bad_point || refusedDirection(normal) || refusedDirection(sun) || bad_moon,
        [&] {
          expectPhysical(sky.irradiance(point, normal, {sun, moon}), "eclipse irradiance");
        },
        "eclipse irradiance");
    // The batch path: float directions, one hostile among ordinary ones.
    const glm::vec3 ray(view);
    std::vector<float> x{0.0f, static_cast<float>(ray.x)}, y{0.6f, static_cast<float>(ray.y)},
        z{0.8f, static_cast<float>(ray.z)};
    std::vector<float> radiance(2 * kMaxChannels), transmittance(2 * kMaxChannels);
    SpectrumBatch l{}, t{};
    for (int c = 0; c < sky.channelCount(); ++c) {
      l.channel[c] = radiance.data() + 2 * c;
      t.channel[c] = transmittance.data() + 2 * c;
    }
    const glm::dvec3 float_view(ray);
    expectContract(
        bad_camera || refusedDirection(float_view) || refusedDirection(sun),
        [&] {
          sky.skyRadianceBatch(camera, sun, {x.data(), y.data(), z.data(), 2}, l, t);
          for (size_t i = 0; i < radiance.size(); ++i) {
            ASSERT_TRUE(std::isfinite(radiance[i]) && radiance[i] >= 0.0f) << "batch radiance " << i;
            ASSERT_TRUE(transmittance[i] >= 0.0f && transmittance[i] <= 1.0f) << "batch transmittance " << i;
          }
        },
        "skyRadianceBatch");
  }
}

// Normalised: a direction of any finite length reads as its unit vector
// (within the float results' rounding), so a view of length 1e-30 no longer
// reads another direction's radiance.
TEST(LookupGeometry, DirectionsOfAnyLengthReadAsTheirUnitVector) {
  const Sky& sky = earth();
  const glm::dvec3 camera(0.0, 0.0, sky.atmosphere().bottom_radius_m + 100.0);
  const glm::dvec3 view = glm::normalize(glm::dvec3(0.3, 0.1, 0.5));
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.8, 0.0, 0.4));
  const RadianceAndTransmittance unit = sky.skyRadiance(camera, view, sun);
  for (double length : {1e-30, 1e-3, 7.0, 1e38, 1e300}) {
    SCOPED_TRACE(length);
    const RadianceAndTransmittance scaled = sky.skyRadiance(camera, view * length, sun * length);
    for (int c = 0; c < sky.channelCount(); ++c) {
      // 1e-6: the normalised vector differs from `view` in its last bits,
      // which moves a float radiance by a few ulps at most.
      EXPECT_NEAR(scaled.radiance[c], unit.radiance[c], 1e-6 * unit.radiance[c]);
      EXPECT_NEAR(scaled.transmittance[c], unit.transmittance[c], 1e-6);
    }
  }
  try {
    sky.skyRadiance(camera, glm::dvec3(0.0), sun);
    FAIL() << "a zero view direction was looked up";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "view direction = (0, 0, 0): a direction needs a length above 0");
  }
  try {
    sky.skyRadiance(glm::dvec3(0.0, kNaN, 7e6), view, sun);
    FAIL() << "a NaN camera was looked up";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "camera = (0, nan, 7e+06): not finite");
  }
}

// Clamped: a camera beyond kMaxPositionDistance_m reads as one at that
// distance on the same line from the centre (at 1e300 m it gave NaN).
TEST(LookupGeometry, FarCamerasReadAsAtTheLargestDistance) {
  const Sky& sky = earth();
  const glm::dvec3 up(0.0, 0.0, 1.0);
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.3, 0.0, 1.0));
  const RadianceAndTransmittance at_reach = sky.skyRadiance(up * kMaxPositionDistance_m, -up, sun);
  EXPECT_GT(at_reach.radiance[1], 0.0f);  // straight down at the sunlit pole: the day sky and ground
  for (double distance : {1e13, 1e100, 1e300}) {
    const RadianceAndTransmittance far = sky.skyRadiance(up * distance, -up, sun);
    EXPECT_EQ(far.radiance, at_reach.radiance) << distance;
    EXPECT_EQ(far.transmittance, at_reach.transmittance) << distance;
  }
}

// A camera inside the moon sees its dark inside; a negative or NaN radius is
// refused rather than read as no moon.
TEST(LookupGeometry, MoonsAreCheckedAndTheirInsideIsDark) {
  const Sky& sky = earth();
  const glm::dvec3 camera(0.0, 0.0, sky.atmosphere().bottom_radius_m + 10.0);
  const glm::dvec3 sun(0.0, 0.0, 1.0);
  const RadianceAndTransmittance inside = sky.skyRadiance(camera, sun, {sun, Moon{camera + 5.0 * sun, 100.0}});
  EXPECT_EQ(inside.radiance, Spectrum(0.0f));
  EXPECT_EQ(inside.transmittance, Spectrum(0.0f));
  for (double radius : {-1.0, kNaN}) {
    // Every lookup that takes a Sunlight checks its moon.
    const Sunlight bad{sun, Moon{camera + 1e8 * sun, radius}};
    EXPECT_THROW(sky.skyRadiance(camera, sun, bad), Error) << radius;
    EXPECT_THROW(sky.radianceToPoint(camera, camera + 1e3 * sun, bad), Error) << radius;
    EXPECT_THROW(sky.sunIrradiance(camera, sun, bad), Error) << radius;
  }
}

}  // namespace
}  // namespace skybake
