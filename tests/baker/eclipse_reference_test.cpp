// The reference under a solar eclipse: the moon hides the sun in every sun
// connection, so the umbra is dark but for the light of the sunlit air
// around it; eclipse queries have cache keys of their own; the eclipse
// query set's rays to points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <utility>

#include "baker/reference/reference_solver.h"
#include "baker/validation/validation.h"
#include "baker/validation/validation_queries.h"
#include "data_formats/config.h"

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
  const QuerySet set = querySetNamed("eclipse", 100e3);
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
  const QuerySet set = querySetNamed("eclipse", 100e3);
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

}  // namespace
}  // namespace skybake
