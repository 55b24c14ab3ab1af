// The reference under a solar eclipse: the moon hides the sun in every sun
// connection, so the umbra is dark but for the light of the sunlit air
// around it; eclipse queries have cache keys of their own.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/reference/reference_solver.h"
#include "baker/validation/validation.h"
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

}  // namespace
}  // namespace skybake
