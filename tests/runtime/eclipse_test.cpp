// Solar eclipses: the moon's occlusion of the sun disk (exact disc overlap,
// parallax, umbra), the neighbourhood average that scales multiple
// scattering, and the Sky's eclipse lookups against direct integration.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

#include <glm/geometric.hpp>

#include "baker/numerics/optical_depth_integral.h"
#include "data_formats/error.h"
#include "direct_single_scattering.h"
#include "runtime/physics/atmosphere_media.h"
#include "runtime/physics/eclipse_skylight.h"
#include "runtime/physics/moon_occluder.h"
#include "runtime/physics/ray_quadrature.h"
#include "runtime/physics/sun_disk.h"
#include "runtime/sky.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

const Sky& bakedSky(const char* file) {
  static std::map<std::string, Sky> skies;
  auto it = skies.find(file);
  if (it == skies.end()) it = skies.emplace(file, Sky::load(fs::path(SKYBAKE_TEST_BAKE_DIR) / file)).first;
  return it->second;
}

glm::dvec3 direction(double zenith_deg, double azimuth_deg) {
  const double t = radiansFromDegrees(zenith_deg), p = radiansFromDegrees(azimuth_deg);
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// The sun's direction turned by `angle_rad` toward +y (the moon's offset).
glm::dvec3 offsetFrom(const glm::dvec3& sun, double angle_rad) {
  const glm::dvec3 side = glm::normalize(glm::cross(sun, glm::dvec3(1.0, 0.0, 0.0)));
  return glm::normalize(sun * std::cos(angle_rad) + side * std::sin(angle_rad));
}

// Overlap area of two discs counted on a grid of cells: the cells' centres
// inside both. Each cell of side h on the boundaries is miscounted by at
// most its area, so the error is below (perimeters / h) h^2 / 2 on average
// far less; 2000 cells across the smaller disc give ~1e-3 relative.
double gridOverlapArea(double a, double b, double d) {
  const int n = 2000;
  const double h = 2.0 * a / n;
  double count = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = -a + (i + 0.5) * h;
    for (int j = 0; j < n; ++j) {
      const double y = -a + (j + 0.5) * h;
      if (x * x + y * y <= a * a && (x - d) * (x - d) + y * y <= b * b) count += 1.0;
    }
  }
  return count * h * h;
}

TEST(Eclipse, DiscOverlapIsTheExactLens) {
  // Closed forms: disjoint, contained, and two equal discs one radius apart
  // (a lens of r^2 (2 pi / 3 - sqrt(3) / 2)).
  EXPECT_EQ(discOverlapArea(1.0, 0.5, 1.6), 0.0);
  EXPECT_NEAR(discOverlapArea(1.0, 0.5, 0.3), kPi * 0.25, 1e-15);
  EXPECT_NEAR(discOverlapArea(0.5, 1.0, 0.3), kPi * 0.25, 1e-15);
  EXPECT_NEAR(discOverlapArea(1.0, 1.0, 1.0), 2.0 * kPi / 3.0 - std::sqrt(3.0) / 2.0, 1e-14);
  for (auto [a, b, d] : {std::array{1.0, 0.7, 0.9}, std::array{1.0, 1.05, 0.4}, std::array{1.0, 0.3, 1.1}}) {
    EXPECT_NEAR(discOverlapArea(a, b, d) / gridOverlapArea(a, b, d), 1.0, 3e-3) << a << " " << b << " " << d;
  }
}

TEST(Eclipse, VisibleFractionOfPartialAnnularAndTotalEclipses) {
  const double sun = radiansFromDegrees(0.2666);
  // Total: a larger moon centred; annular: a smaller one centred leaves the
  // ring 1 - (moon / sun)^2; far apart: all of it.
  EXPECT_EQ(sunFractionPastMoonDisc(sun, 1.05 * sun, 0.0), 0.0);
  EXPECT_NEAR(sunFractionPastMoonDisc(sun, 0.9 * sun, 0.05 * sun), 1.0 - 0.81, 1e-12);
  EXPECT_EQ(sunFractionPastMoonDisc(sun, 0.9 * sun, 2.0 * sun), 1.0);
  // Non-decreasing and continuous as the moon moves off (steps of 1e-3 sun
  // radii change it by at most the lens's slope, below 2e-3 per step).
  double last = 0.0;
  for (int i = 0; i <= 2100; ++i) {
    const double f = sunFractionPastMoonDisc(sun, 1.02 * sun, i * 1e-3 * sun);
    EXPECT_GE(f, last - 1e-12);
    EXPECT_LE(f - last, 2e-3);
    last = f;
  }
  EXPECT_EQ(last, 1.0);
  // A point sun is all hidden or all free.
  EXPECT_EQ(sunFractionPastMoonDisc(0.0, sun, 0.5 * sun), 0.0);
  EXPECT_EQ(sunFractionPastMoonDisc(0.0, sun, 1.5 * sun), 1.0);
}

TEST(Eclipse, ParallaxMakesANarrowUmbra) {
  const double sun_radius = radiansFromDegrees(0.2666);
  const double moon_radius = 1.03 * sun_radius;
  const glm::dvec3 camera(0.0, 0.0, 6360e3), sun = direction(50.0, 0.0);
  const Moon moon = Moon::seenFrom(camera, sun, moon_radius);
  EXPECT_NEAR(std::asin(moon.radius_m / kMeanLunarDistance_m), moon_radius, 1e-15);
  EXPECT_EQ(moon.visibleSunFraction(camera, sun, sun_radius), 0.0);
  // The umbra's radius across the sun is the distance times the difference
  // of the angular radii (small angles: to 1e-4 relative here); just inside
  // it totality, just outside a sliver of sun, and a thousand kilometres
  // away a partial eclipse.
  const double umbra_m = kMeanLunarDistance_m * (moon_radius - sun_radius);
  const glm::dvec3 across = glm::normalize(glm::cross(sun, glm::dvec3(0.0, 1.0, 0.0)));
  EXPECT_EQ(moon.visibleSunFraction(camera + across * (0.98 * umbra_m), sun, sun_radius), 0.0);
  const double outside = moon.visibleSunFraction(camera + across * (1.02 * umbra_m), sun, sun_radius);
  EXPECT_GT(outside, 0.0);
  EXPECT_LT(outside, 1e-3);
  const double far = moon.visibleSunFraction(camera + across * 1e6, sun, sun_radius);
  EXPECT_GT(far, 0.2);
  EXPECT_LT(far, 0.9);
  // No moon hides nothing.
  EXPECT_EQ(Moon{}.visibleSunFraction(camera, sun, sun_radius), 1.0);
}

TEST(Eclipse, SkylightFractionIntegratesTheNeighbourhood) {
  const Sky& sky = bakedSky("earth.exr");
  const AtmosphereParameters& a = sky.atmosphere();
  const glm::dvec3 camera(0.0, 0.0, a.bottom_radius_m), sun = direction(50.0, 0.0);
  const double alpha = a.sun_angular_radius_rad;
  // Totality at the umbra's centre, inside it off centre, and a partial
  // eclipse, on the ground and at 10 km: F against the same kernel
  // integrated over 16 times the directions and 8 times the distances.
  // 8 % relative: the directions near the horizon at 10 km, where the
  // paths through the air are longest (measured at 5 %).
  for (double altitude : {0.0, 10000.0}) {
    const glm::dvec3 point(0.0, 0.0, a.bottom_radius_m + altitude);
    for (double offset_rad : {0.0, 0.00002, 0.003}) {
      const Moon moon = Moon::seenFrom(camera, offsetFrom(sun, offset_rad), 1.04 * alpha);
      const Spectrum f = eclipseSkylightFraction(a, moon, point, sun);
      const Spectrum fine = eclipseSkylightFraction(a, moon, point, sun, 64, 32, 256);
      for (int c = 0; c < a.channelCount(); ++c) {
        EXPECT_NEAR(f[c] / fine[c], 1.0, 0.08)
            << "altitude " << altitude << " offset " << offset_rad << " channel " << c;
        // Totality's sky is lit from outside the umbra, never black.
        EXPECT_GT(f[c], 0.0);
      }
    }
  }
  // A moon far from the sun leaves the sky as it is.
  const Spectrum far = eclipseSkylightFraction(a, Moon::seenFrom(camera, offsetFrom(sun, 0.1), alpha), camera, sun);
  for (int c = 0; c < a.channelCount(); ++c) EXPECT_EQ(far[c], 1.0f);
}

// Single scattering with the moon by direct integration
// (direct_single_scattering.h), 400 x 4 Gauss nodes along the ray.
Spectrum directEclipsedSingle(const AtmosphereParameters& a, const glm::dvec3& camera, const glm::dvec3& view,
                              const glm::dvec3& sun, const Moon& moon) {
  return directSingleScatteringFrom(a, camera, view, sun, 0.0, 400, moon);
}

TEST(Eclipse, SingleScatteringFollowsTheMoonsShadow) {
  // A bake with one order: its sky is single scattering alone.
  const Sky& sky = bakedSky("earth_single.exr");
  const AtmosphereParameters& a = sky.atmosphere();
  const glm::dvec3 sun = direction(50.0, 0.0);
  // Partial eclipses from the ground and from 10 km, and a camera a few
  // hundred km outside a total eclipse's umbra looking across it.
  for (double altitude : {0.0, 10000.0}) {
    const glm::dvec3 camera(0.0, 0.0, a.bottom_radius_m + altitude);
    for (double offset_rad : {0.002, 0.004, 0.0005}) {
      const Moon moon = Moon::seenFrom(camera, offsetFrom(sun, offset_rad), 1.03 * a.sun_angular_radius_rad);
      for (auto [zenith, azimuth] : {std::array{0.0, 0.0}, std::array{60.0, 90.0}, std::array{85.0, 180.0},
                                     std::array{80.0, 0.0}, std::array{88.0, 270.0}}) {
        const glm::dvec3 view = direction(zenith, azimuth);
        const Spectrum eclipsed = sky.skyRadiance(camera, view, {sun, moon}).radiance;
        const Spectrum direct = directEclipsedSingle(a, camera, view, sun, moon);
        for (int c = 0; c < 3; ++c) {
          // 2 %: the tables' own 1 % bound (sky_test's) plus the ratio's
          // quadrature, 16 sub-intervals against 400 across a penumbra.
          EXPECT_NEAR(eclipsed[c] / direct[c], 1.0, 0.02)
              << "altitude " << altitude << " offset " << offset_rad << " view " << zenith << "," << azimuth;
        }
      }
    }
  }
}

// Aerial perspective under partial eclipses (and a camera just outside a
// total one's umbra): radiance to points 5 to 120 km away against the
// direct single-scattering integral with the moon, in the one-order bake.
TEST(Eclipse, RadianceToPointFollowsTheMoonsShadow) {
  const Sky& sky = bakedSky("earth_single.exr");
  const AtmosphereParameters& a = sky.atmosphere();
  const glm::dvec3 sun = direction(50.0, 0.0);
  for (double altitude : {0.0, 10000.0}) {
    const glm::dvec3 camera(0.0, 0.0, a.bottom_radius_m + altitude);
    for (double offset_rad : {0.002, 0.0005}) {
      const Moon moon = Moon::seenFrom(camera, offsetFrom(sun, offset_rad), 1.03 * a.sun_angular_radius_rad);
      for (auto [zenith, azimuth] :
           {std::array{60.0, 90.0}, std::array{85.0, 180.0}, std::array{80.0, 0.0}, std::array{88.0, 270.0}}) {
        const glm::dvec3 view = direction(zenith, azimuth);
        for (double distance_m : {5e3, 30e3, 120e3}) {
          const Spectrum eclipsed = sky.radianceToPoint(camera, camera + view * distance_m, {sun, moon}).radiance;
          const Spectrum direct = directSingleScatteringFrom(a, camera, view, sun, distance_m, 400, moon);
          for (int c = 0; c < 3; ++c) {
            // 2 %: the segment lookup's own error (the plain one's less its
            // integral is what leaks into the scaled part) plus the
            // integral's, 16 sub-intervals against 400.
            EXPECT_NEAR(eclipsed[c] / direct[c], 1.0, 0.02)
                << "altitude " << altitude << " offset " << offset_rad << " view " << zenith << "," << azimuth
                << " distance " << distance_m;
          }
        }
      }
    }
  }
  // A moon 5 deg from the sun: the plain radiance to the point, exactly.
  const glm::dvec3 camera(0.0, 0.0, a.bottom_radius_m + 500.0), view = direction(80.0, 30.0);
  const Moon far = Moon::seenFrom(camera, direction(45.0, 0.0), 1.03 * a.sun_angular_radius_rad);
  const RadianceAndTransmittance plain = sky.radianceToPoint(camera, camera + view * 20e3, sun);
  const RadianceAndTransmittance eclipsed = sky.radianceToPoint(camera, camera + view * 20e3, {sun, far});
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(plain.radiance[c], eclipsed.radiance[c]);
    EXPECT_EQ(plain.transmittance[c], eclipsed.transmittance[c]);
  }
}

// Light shafts under a partial eclipse (a Sunlight with a moon and a shadow
// length together): the lit part of each ray against the direct
// single-scattering integral with the moon over that part, in the
// one-order bake; a moon that hides nothing leaves the plain lookups with
// the same shadow exactly.
TEST(Eclipse, LightShaftsFollowTheMoonsShadow) {
  const Sky& sky = bakedSky("earth_single.exr");
  const AtmosphereParameters& a = sky.atmosphere();
  const glm::dvec3 sun = direction(50.0, 0.0);
  const glm::dvec3 camera(0.0, 0.0, a.bottom_radius_m + 500.0);
  const Moon moon = Moon::seenFrom(camera, offsetFrom(sun, 0.002), 1.03 * a.sun_angular_radius_rad);
  const Moon far = Moon::seenFrom(camera, direction(45.0, 0.0), 1.03 * a.sun_angular_radius_rad);
  for (auto [zenith, azimuth] : {std::array{60.0, 90.0}, std::array{80.0, 0.0}, std::array{85.0, 180.0}}) {
    const glm::dvec3 view = direction(zenith, azimuth);
    for (double shadow_m : {2e3, 10e3}) {
      // The sky: lit from shadow_m to the ray's end, which is the whole
      // ray's integral less that of its first shadow_m (the same
      // transmittance from the camera weighs both).
      const Spectrum sky_lit = sky.skyRadiance(camera, view, {sun, moon}, shadow_m).radiance;
      const Spectrum direct_sky = directSingleScatteringFrom(a, camera, view, sun, 0.0, 400, moon) -
                                  directSingleScatteringFrom(a, camera, view, sun, shadow_m, 400, moon);
      // A point 30 km away: lit from the camera to shadow_m before it.
      const glm::dvec3 point = camera + view * 30e3;
      const Spectrum to_point = sky.radianceToPoint(camera, point, {sun, moon}, shadow_m).radiance;
      const Spectrum direct_to_point = directSingleScatteringFrom(a, camera, view, sun, 30e3 - shadow_m, 400, moon);
      for (int c = 0; c < 3; ++c) {
        // 2 %, as for the eclipse lookups without a shadow: the tables' 1 %
        // plus the ratio's quadrature (16 sub-intervals against 400).
        EXPECT_NEAR(sky_lit[c] / direct_sky[c], 1.0, 0.02) << zenith << "," << azimuth << " shadow " << shadow_m;
        EXPECT_NEAR(to_point[c] / direct_to_point[c], 1.0, 0.02) << zenith << "," << azimuth << " shadow " << shadow_m;
      }
      const RadianceAndTransmittance plain = sky.skyRadiance(camera, view, sun, shadow_m),
                                     far_moon = sky.skyRadiance(camera, view, {sun, far}, shadow_m);
      const RadianceAndTransmittance plain_point = sky.radianceToPoint(camera, point, sun, shadow_m),
                                     far_point = sky.radianceToPoint(camera, point, {sun, far}, shadow_m);
      for (int c = 0; c < 4; ++c) {
        EXPECT_EQ(plain.radiance[c], far_moon.radiance[c]);
        EXPECT_EQ(plain_point.radiance[c], far_point.radiance[c]);
        EXPECT_EQ(plain_point.transmittance[c], far_point.transmittance[c]);
      }
    }
  }
}

TEST(Eclipse, TotalityIsDarkButNotBlackAndAFarMoonChangesNothing) {
  const Sky& sky = bakedSky("earth.exr");
  const AtmosphereParameters& a = sky.atmosphere();
  const glm::dvec3 camera(0.0, 0.0, a.bottom_radius_m), sun = direction(50.0, 0.0), zenith(0.0, 0.0, 1.0);
  const Moon total = Moon::seenFrom(camera, sun, 1.03 * a.sun_angular_radius_rad);
  const Spectrum plain = sky.skyRadiance(camera, zenith, sun).radiance;
  const Spectrum dark = sky.skyRadiance(camera, zenith, {sun, total}).radiance;
  for (int c = 0; c < 3; ++c) {
    // Totality's zenith: lit by the air outside the umbra, from 1e-5 to 1e-2
    // of the day sky (observed totality skies are 1e-4 to 1e-3 of it).
    EXPECT_GT(dark[c], 1e-5f * plain[c]) << c;
    EXPECT_LT(dark[c], 1e-2f * plain[c]) << c;
  }
  EXPECT_EQ(sky.sunIrradiance(camera, zenith, {sun, total})[1], 0.0f);
  const SunAndSkyIrradiance lit = sky.irradiance(camera, zenith, sun),
                            eclipsed = sky.irradiance(camera, zenith, {sun, total});
  EXPECT_LT(eclipsed.sky[1], 1e-2f * lit.sky[1]);
  EXPECT_GT(eclipsed.sky[1], 0.0f);
  // A moon 5 deg from the sun hides it from nowhere: the plain lookups' values.
  const Moon far = Moon::seenFrom(camera, offsetFrom(sun, 0.09), a.sun_angular_radius_rad);
  for (auto [z, az] : {std::array{0.0, 0.0}, std::array{70.0, 90.0}, std::array{95.0, 180.0}}) {
    const glm::dvec3 view = direction(z, az);
    const RadianceAndTransmittance p = sky.receivedRadiance(camera, view, sun);
    const RadianceAndTransmittance e = sky.receivedRadiance(camera, view, {sun, far});
    for (int c = 0; c < 4; ++c) {
      EXPECT_EQ(p.radiance[c], e.radiance[c]);
      EXPECT_EQ(p.transmittance[c], e.transmittance[c]);
    }
  }
}

}  // namespace
}  // namespace skybake

namespace skybake {
namespace {

// Hostile moons: one around the camera, one the size of the sky, one in the
// atmosphere beside the camera. Every lookup stays finite and non-negative
// (a camera inside the moon sees its dark inside); one at a NaN position is
// refused.
TEST(Eclipse, HostileMoonsGiveFiniteLight) {
  const Sky& sky = bakedSky("earth.exr");
  const AtmosphereParameters& a = sky.atmosphere();
  const glm::dvec3 camera(0.0, 0.0, a.bottom_radius_m + 1000.0), sun = direction(50.0, 0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // A moon whose centre is not finite is refused (runtime/lookup_geometry.h), not read as no moon.
  EXPECT_THROW(sky.receivedRadiance(camera, sun, {sun, Moon{glm::dvec3(nan, 0.0, 0.0), 1.7e6}}), Error);
  for (const Moon& moon : {Moon{camera, 5000.0}, Moon{camera + sun * 1e9, 1e9}, Moon{camera + sun * 20e3, 3e3}}) {
    for (auto [z, az] : {std::array{0.0, 0.0}, std::array{50.0, 0.0}, std::array{89.0, 90.0}, std::array{120.0, 0.0}}) {
      const RadianceAndTransmittance v = sky.receivedRadiance(camera, direction(z, az), {sun, moon});
      const SunAndSkyIrradiance e = sky.irradiance(camera, {0.0, 0.0, 1.0}, {sun, moon});
      for (int c = 0; c < a.channelCount(); ++c) {
        EXPECT_TRUE(std::isfinite(v.radiance[c]) && v.radiance[c] >= 0.0f) << v.radiance[c];
        EXPECT_TRUE(std::isfinite(e.sun[c]) && e.sun[c] >= 0.0f);
        EXPECT_TRUE(std::isfinite(e.sky[c]) && e.sky[c] >= 0.0f);
      }
    }
  }
}

}  // namespace
}  // namespace skybake
