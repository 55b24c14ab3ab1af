// The reference under a solar eclipse: the moon hides the sun in every sun
// connection, so the umbra is dark but for the light of the sunlit air
// around it; eclipse queries have cache keys of their own; the eclipse
// query set's rays to points and irradiance queries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <utility>

#include "baker/bake/bake.h"
#include "baker/reference/reference_solver.h"
#include "baker/validation/validation.h"
#include "baker/validation/validation_queries.h"
#include "data_formats/config/config.h"
#include "runtime/sky.h"
#include "test_configs.h"

namespace skybake {
namespace {

TEST(EclipseReference, TheMoonDarkensTheUmbraButNotToBlack) {
  const BakeConfig config = builtinEarthConfig();
  const AtmosphereParameters& a = config.atmosphere;
  const RadianceQuery plain{0.0, 50.0, 0.0, 0.0, 0.0};
  RadianceQuery total = plain, far = plain;
  total.moon = {0.0, 0.28};
  far.moon = {5.0, 0.28};
  const ReferenceSolver solver(a);
  const QueryGeometry g = geometryOf(a, plain), gt = geometryOf(a, total), gf = geometryOf(a, far);
  const ReferenceRay ray{g.camera, g.view, g.sun, 0.0};
  constexpr int kPaths = 4096;
  constexpr uint64_t kSeed = 7;
  const ReferenceEstimate day = solver.radiance(ray, kPaths, kSeed);
  const ReferenceEstimate away = solver.radiance(ray, kPaths, kSeed, gf.moon);
  const ReferenceEstimate dark = solver.radiance(ray, kPaths, kSeed, gt.moon);
  // Single scattering alone (0 paths): the zenith ray stays in the umbra
  // through all of the air that scatters (it leaves the 90 km wide shadow
  // cylinder above 100 km), so nothing.
  const ReferenceEstimate dark_single = solver.radiance(ray, 0, kSeed, gt.moon);
  for (int c = 0; c < a.channelCount(); ++c) {
    // A moon 5 deg from the sun hides it from no point a path reaches: the
    // same paths give the same sum.
    EXPECT_EQ(away.value[c], day.value[c]);
    EXPECT_LT(dark_single.value[c], 1e-12 * day.value[c]);
    // Totality is lit by scattering from outside the umbra: between 1e-5
    // and 1e-2 of the day sky (observed: 1e-4 to 1e-3); 4096 paths estimate
    // it to a few percent, far inside these bounds.
    EXPECT_GT(dark.value[c], 1e-5 * day.value[c]) << c;
    EXPECT_LT(dark.value[c], 1e-2 * day.value[c]) << c;
  }
  // Eclipses never read or overwrite the plain sky's cache entries.
  EXPECT_NE(radianceKey(plain), radianceKey(total));
  EXPECT_NE(radianceKey(total), radianceKey(far));
  EXPECT_EQ(radianceKey(plain), radianceKey(RadianceQuery{0.0, 50.0, 0.0, 0.0, 0.0}));
}

TEST(EclipseReference, TheEclipseQuerySetHasEveryCase) {
  const QuerySet set = querySetNamed("eclipse", 6360e3, 6460e3);
  ASSERT_FALSE(set.radiance.empty());
  bool total = false, annular = false, partial = false, plain = false;
  for (const RadianceQuery& q : set.radiance) {
    plain |= !q.moon.present();
    total |= q.moon.angular_radius_deg > 0.2666 && q.moon.separation_deg == 0.0;
    annular |= q.moon.angular_radius_deg < 0.2666 && q.moon.separation_deg == 0.0;
    partial |= q.moon.separation_deg > 0.1;
  }
  EXPECT_TRUE(total && annular && partial);
  EXPECT_FALSE(plain);
}

// Rays to points under the eclipse: totality with the camera inside the
// umbra (at its centre and off its axis) and outside it (0.03 deg), a
// partial and an annular eclipse, from both cameras, at distances from 5 to
// 120 km; and a query CSV may give a row both a distance and a moon.
TEST(EclipseReference, TheEclipseQuerySetHasRaysToPoints) {
  const QuerySet set = querySetNamed("eclipse", 6360e3, 6460e3);
  std::set<std::pair<double, double>> moons;
  std::set<double> altitudes;
  double nearest_m = 1e30, farthest_m = 0.0;
  size_t to_points = 0;
  for (const RadianceQuery& q : set.radiance) {
    if (q.distance_m <= 0.0) continue;
    ++to_points;
    EXPECT_TRUE(q.moon.present());
    moons.insert({q.moon.separation_deg, q.moon.angular_radius_deg});
    altitudes.insert(q.altitude_m);
    nearest_m = std::min(nearest_m, q.distance_m);
    farthest_m = std::max(farthest_m, q.distance_m);
  }
  for (const auto& moon : {std::pair{0.0, 0.28}, std::pair{0.006, 0.28}, std::pair{0.03, 0.28}, std::pair{0.25, 0.28},
                           std::pair{0.0, 0.25}}) {
    EXPECT_EQ(moons.count(moon), 1u) << moon.first << " " << moon.second;
  }
  EXPECT_EQ(altitudes, (std::set<double>{0.0, 10000.0}));
  EXPECT_LE(nearest_m, 5000.0);
  EXPECT_GE(farthest_m, 120000.0);
  // validate's cost is its reference's, about the same per query: at most
  // half as many rays to points as sky rays keeps it within 1.5 times.
  EXPECT_LE(2 * to_points, set.radiance.size() - to_points);

  const std::filesystem::path csv = std::filesystem::path(::testing::TempDir()) / "eclipse_points.csv";
  {
    std::ofstream out(csv);
    out << "altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m,moon_separation_deg,"
           "moon_angular_radius_deg\n0,50,85,0,20000,0,0.28\n";
  }
  const QuerySet from_csv = querySetFromCsv(csv);
  ASSERT_EQ(from_csv.radiance.size(), 1u);
  EXPECT_EQ(from_csv.radiance[0].distance_m, 20000.0);
  EXPECT_EQ(from_csv.radiance[0].moon.angular_radius_deg, 0.28);
}

// A CSV with the columns of `lookup irradiance` alone asks for sky
// irradiance there, and nothing else.
TEST(QueryCsv, IrradianceColumnsAloneAskForSkyIrradiance) {
  const std::filesystem::path irradiance_csv = std::filesystem::path(::testing::TempDir()) / "irradiance_points.csv";
  {
    std::ofstream out(irradiance_csv);
    out << "sun_zenith_deg,altitude_m\n30,2000\n96.5,44000\n";
  }
  const QuerySet irradiance = querySetFromCsv(irradiance_csv);
  EXPECT_TRUE(irradiance.radiance.empty());
  ASSERT_EQ(irradiance.irradiance.size(), 2u);
  EXPECT_EQ(irradiance.irradiance[1].altitude_m, 44000.0);
  EXPECT_EQ(irradiance.irradiance[1].sun_zenith_deg, 96.5);
  EXPECT_FALSE(irradiance.irradiance[1].moon.present());
}

// The eclipse set's sky irradiance: on the ground and at 10 km under every
// moon. Their cache keys name the moon; the bake (Sky::irradiance with a
// moon) and the reference (the moon in its sun connections) both see it: a
// moon far from the sun changes nothing, totality leaves the light of the
// sunlit air beyond the umbra.
TEST(EclipseReference, IrradianceQueriesSeeTheMoonInTheBakeAndTheReference) {
  const QuerySet set = querySetNamed("eclipse", 6360e3, 6460e3);
  std::set<std::pair<double, double>> moons;
  for (const IrradianceQuery& q : set.irradiance) {
    EXPECT_TRUE(q.moon.present());
    moons.insert({q.moon.separation_deg, q.moon.angular_radius_deg});
  }
  EXPECT_EQ(set.irradiance.size(), 12u);
  EXPECT_EQ(moons.size(), 6u);
  EXPECT_EQ(moons.count({0.0, 0.28}), 1u);

  const IrradianceQuery plain{0.0, 50.0}, total{0.0, 50.0, {0.0, 0.28}}, far{0.0, 50.0, {5.0, 0.28}};
  EXPECT_NE(irradianceKey(plain), irradianceKey(total));
  EXPECT_NE(irradianceKey(total), irradianceKey(far));
  const QuerySet queries{"irradiance under a moon", {}, {plain, total, far}};

  SilentProgress silent;
  const BakeConfig config = test::smallEarth(4);
  const Sky sky(bakeAtmosphere(config, 0, silent).file);
  const MethodValues bake = evaluateBake(sky, queries);
  ReferenceSettings settings;
  settings.paths = 1024;
  settings.cache_directory.clear();
  const ReferenceValues reference = computeReferenceValues(config.atmosphere, queries, settings, silent);
  for (int c = 0; c < config.atmosphere.channelCount(); ++c) {
    // A moon 5 deg away hides the sun from nowhere: the plain lookup, and
    // (each query's paths seeded by its key) the plain value within the
    // noise: 4 standard errors of the difference of two estimates.
    EXPECT_EQ(bake.irradiance[2][c], bake.irradiance[0][c]) << c;
    const CachedReference &r_plain = reference.irradiance[0], &r_far = reference.irradiance[2];
    EXPECT_NEAR(r_far.value[c], r_plain.value[c], 4.0 * std::hypot(r_far.standard_error[c], r_plain.standard_error[c]))
        << c;
    // Totality: between 1e-5 and 1e-2 of the plain sky's irradiance in both
    // (as the zenith radiance above; 1024 paths estimate it to some 10 %).
    for (double ratio : {double(bake.irradiance[1][c]) / bake.irradiance[0][c],
                         reference.irradiance[1].value[c] / reference.irradiance[0].value[c]}) {
      EXPECT_GT(ratio, 1e-5) << c;
      EXPECT_LT(ratio, 1e-2) << c;
    }
  }
}

}  // namespace
}  // namespace skybake
