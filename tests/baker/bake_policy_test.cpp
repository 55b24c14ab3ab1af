// Bake policy: which scene ranges a bake narrows its tables to, and the
// sizes its orders iterate on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "baker/bake/bake_policy.h"
#include "data_formats/config/config.h"
#include "data_formats/parameterization/texture_mapping.h"

namespace skybake {
namespace {

// Texture coordinates are computed in double from distances up to ~1e7 m;
// round-off stays near 1e-12. 1e-9 of the unit range is 1e-7 of a texel at
// 128 texels: any real mapping error is far larger.
constexpr double kCoordTolerance = 1e-9;

double centre(int i, int n) { return (i + 0.5) / n; }

// The whole-axis sun texels of a config (the iteration's), in degrees.
double sunTexelZenithDeg(const AtmosphereDomain& d, const ScatteringSizes& sizes, int i) {
  return std::acos(muSFromScatteringTexel(d, sizes, i)) / radiansFromDegrees(1.0);
}

// A scene's ranges narrow the 4D axes: texels still round-trip, the r axis
// ends on the range's altitudes, and the sun axis covers the range plus its
// 1 deg margin on the iteration's own sun texels, one of them on the horizon.
TEST(BakePolicy, NarrowedScatteringAxesRoundTripAndEndOnTheSceneRanges) {
  BakeConfig config = builtinEarthConfig();
  const AtmosphereDomain domain = AtmosphereDomain::fromParameters(config.atmosphere);
  const ScatteringSizes whole_sizes = ScatteringSizes::fromTextureSizes(config.sizes);
  config.scene_ranges.altitude_m = std::array<double, 2>{500.0, 2000.0};
  config.scene_ranges.sun_zenith_deg = std::array<double, 2>{20.0, 90.0};
  config = settledBakeConfig(config);
  const AtmosphereDomain narrow = sceneDomain(config);
  const ScatteringSizes sizes = ScatteringSizes::fromTextureSizes(config.sizes);
  ASSERT_TRUE(narrow.narrowed());
  EXPECT_FALSE(domain.narrowed());
  // The r axis ends on the settled range, which holds the scene's (widened
  // to the whole axis's texels); r comes back through sqrt(rho^2 + R^2)
  // with R = 6.36e6 m: ~1e-9 m.
  const std::array<double, 2> altitudes = config.scene_ranges.altitude_m.value();
  EXPECT_LE(altitudes[0], 500.0);
  EXPECT_GE(altitudes[1], 2000.0);
  EXPECT_NEAR(rFromScatteringTexel(narrow, sizes, 0), domain.bottom_radius_m + altitudes[0], 1e-6);
  EXPECT_NEAR(rFromScatteringTexel(narrow, sizes, sizes.r - 1), domain.bottom_radius_m + altitudes[1], 1e-6);
  // Every sun texel is one of the whole axis's, the scene's 19 to 91 deg
  // lies within them, and no whole-axis texel inside it is missing.
  std::vector<double> whole_deg;
  for (int i = 0; i < whole_sizes.mu_s; ++i) whole_deg.push_back(sunTexelZenithDeg(domain, whole_sizes, i));
  double closest_to_horizon = 1.0;
  for (int i = 0; i < sizes.mu_s; ++i) {
    const double deg = sunTexelZenithDeg(narrow, sizes, i);
    double nearest = 180.0;
    for (double w : whole_deg) nearest = std::min(nearest, std::abs(w - deg));
    EXPECT_LT(nearest, 1e-6) << "sun texel " << i << " at " << deg << " deg";
    closest_to_horizon = std::min(closest_to_horizon, std::abs(muSFromScatteringTexel(narrow, sizes, i)));
  }
  EXPECT_LT(closest_to_horizon, 1e-9);
  EXPECT_GE(sunTexelZenithDeg(narrow, sizes, 0), 91.0 - 1e-9);
  EXPECT_LE(sunTexelZenithDeg(narrow, sizes, sizes.mu_s - 1), 19.0 + 1e-9);
  const int inside = static_cast<int>(std::count_if(whole_deg.begin(), whole_deg.end(), [&](double w) {
    return w <= sunTexelZenithDeg(narrow, sizes, 0) + 1e-6 &&
           w >= sunTexelZenithDeg(narrow, sizes, sizes.mu_s - 1) - 1e-6;
  }));
  EXPECT_EQ(inside, sizes.mu_s);
  for (int i_r = 0; i_r < sizes.r; ++i_r) {
    for (int i_mu_s = 0; i_mu_s < sizes.mu_s; ++i_mu_s) {
      const ScatteringTexelConfig c = scatteringTexelConfig(narrow, sizes, i_r, sizes.mu / 2 + 3, i_mu_s, 0);
      const ScatteringCoord u =
          scatteringCoordFromRMuMuSNu(narrow, sizes, c.r, c.mu, c.mu_s, c.nu, c.ray_intersects_ground);
      EXPECT_NEAR(u.u_r, centre(i_r, sizes.r), kCoordTolerance);
      EXPECT_NEAR(u.u_mu, centre(sizes.mu / 2 + 3, sizes.mu), kCoordTolerance);
      EXPECT_NEAR(u.u_mu_s, centre(i_mu_s, sizes.mu_s), kCoordTolerance);
    }
  }
  // The irradiance table keeps the whole sun range.
  EXPECT_NEAR(irradianceTexelConfig(narrow, config.sizes.irradiance_mu_s, config.sizes.irradiance_r, 0, 0).mu_s,
              domain.mu_s_min, 1e-9);
}

// A scene's sun texels given in resolution.scene that are not the
// iteration's span the range itself: the high end on the range's margin,
// the low end moved down by less than a texel to put one on the horizon.
TEST(BakePolicy, GivenSunTexelsSpanTheRangeWithOneOnTheHorizon) {
  BakeConfig config = builtinEarthConfig();
  config.scene_ranges.sun_zenith_deg = std::array<double, 2>{20.0, 90.0};
  config.sizes.scene = std::array<int, 4>{TextureSizes::kChosenByTheBake, TextureSizes::kChosenByTheBake, 30,
                                          TextureSizes::kChosenByTheBake};
  config = settledBakeConfig(config);
  const AtmosphereDomain narrow = sceneDomain(config);
  const ScatteringSizes sizes = ScatteringSizes::fromTextureSizes(config.sizes);
  ASSERT_EQ(sizes.mu_s, 30);
  EXPECT_NEAR(sunTexelZenithDeg(narrow, sizes, sizes.mu_s - 1), 19.0, 1e-6);
  const double lowest_deg = sunTexelZenithDeg(narrow, sizes, 0);
  const double second_deg = sunTexelZenithDeg(narrow, sizes, 1);
  EXPECT_GE(lowest_deg, 91.0 - 1e-9);
  EXPECT_LT(lowest_deg - 91.0, lowest_deg - second_deg);
  double closest_to_horizon = 1.0;
  for (int i = 0; i < sizes.mu_s; ++i) {
    closest_to_horizon = std::min(closest_to_horizon, std::abs(muSFromScatteringTexel(narrow, sizes, i)));
  }
  EXPECT_LT(closest_to_horizon, 1e-9);
}

// The sizes a scene gets from the whole domain's: for the ground-level
// scene (0 to 2 km, sun 0 to 90 deg) the stored tables hold under an eighth
// of the whole bake's 4D texels (the file budget), on an altitude
// axis at least as fine as the whole one's; settling is idempotent, and the
// settled config as the file stores it settles to itself; each axis the
// config gives in resolution.scene or resolution.iteration wins.
TEST(BakePolicy, AScenesSizesComeFromTheWholeDomainsAndGivenAxesWin) {
  const BakeConfig whole = builtinEarthConfig();
  BakeConfig ground = whole;
  ground.scene_ranges.altitude_m = std::array<double, 2>{0.0, 2000.0};
  ground.scene_ranges.sun_zenith_deg = std::array<double, 2>{0.0, 90.0};
  const BakeConfig settled = settledBakeConfig(ground);
  auto texels4d = [](const TextureSizes& s) { return 3.0 * s.scatteringTexels() + densitySizes(s).scatteringTexels(); };
  EXPECT_LT(texels4d(settled.sizes), texels4d(whole.sizes) / 8.0);
  ASSERT_TRUE(settled.sizes.scene && settled.sizes.iteration);
  EXPECT_EQ(*settled.sizes.scene, (std::array<int, 4>{settled.sizes.scattering_r, settled.sizes.scattering_mu,
                                                      settled.sizes.scattering_mu_s, settled.sizes.scattering_nu}));
  // The altitude texels are the whole axis's own over the range, widened
  // to the next of them: 0 to 2 km becomes 0 to 2.25 km on Earth.
  const AtmosphereDomain d = sceneDomain(settled);
  const AtmosphereDomain w = AtmosphereDomain::fromParameters(whole.atmosphere);
  const ScatteringSizes scene_sizes = ScatteringSizes::fromTextureSizes(settled.sizes);
  const ScatteringSizes whole_sizes = ScatteringSizes::fromTextureSizes(whole.sizes);
  ASSERT_TRUE(settled.scene_ranges.altitude_m.has_value());
  EXPECT_EQ((*settled.scene_ranges.altitude_m)[0], 0.0);
  EXPECT_GE((*settled.scene_ranges.altitude_m)[1], 2000.0);
  for (int i = 0; i < scene_sizes.r; ++i) {
    // r comes back through sqrt(rho^2 + R^2) with R = 6.36e6 m: ~1e-9 m.
    EXPECT_NEAR(rFromScatteringTexel(d, scene_sizes, i), rFromScatteringTexel(w, whole_sizes, i), 1e-6);
  }
  EXPECT_GT(rFromScatteringTexel(w, whole_sizes, scene_sizes.r), w.bottom_radius_m + 2000.0);
  // The orders iterate on every sun texel of the whole axis (one sits on the horizon).
  EXPECT_EQ((*settled.sizes.iteration)[2], whole.sizes.scattering_mu_s);
  const BakeConfig again = settledBakeConfig(settled);
  EXPECT_EQ(again.sizes, settled.sizes);
  EXPECT_EQ(again.scene_ranges.altitude_m, settled.scene_ranges.altitude_m);
  EXPECT_EQ(again.scene_ranges.sun_zenith_deg, settled.scene_ranges.sun_zenith_deg);
  EXPECT_EQ(settledBakeConfig(parseConfig(configToToml(settled), "stored")).sizes, settled.sizes);

  constexpr int kChosen = TextureSizes::kChosenByTheBake;
  BakeConfig given = ground;
  given.sizes.scene = std::array<int, 4>{12, kChosen, kChosen, 16};
  given.sizes.iteration = std::array<int, 4>{kChosen, 64, kChosen, kChosen};
  const BakeConfig g = settledBakeConfig(given);
  EXPECT_EQ(*g.sizes.scene, (std::array<int, 4>{12, settled.sizes.scattering_mu, settled.sizes.scattering_mu_s, 16}));
  EXPECT_EQ(*g.sizes.iteration, (std::array<int, 4>{(*settled.sizes.iteration)[0], 64, (*settled.sizes.iteration)[2],
                                                    (*settled.sizes.iteration)[3]}));
  EXPECT_EQ(settledBakeConfig(whole).sizes, whole.sizes);  // nothing narrowed, nothing chosen
}

// A sun range that would not make the sun axis a texel finer is dropped
// (0 to 110 deg plus the 1 deg margin reaches Earth's 0 to 111 deg axis's
// end); one that does (0 to 90 deg, about 16 texels fewer) stays. Either way
// a narrowed bake gets its iteration sizes written out, with every sun
// texel of the whole axis.
TEST(BakePolicy, SettledConfigKeepsOnlySunRangesThatNarrowTheAxis) {
  BakeConfig config = builtinEarthConfig();
  config.scene_ranges.altitude_m = std::array<double, 2>{0.0, 15000.0};
  config.scene_ranges.sun_zenith_deg = std::array<double, 2>{0.0, 110.0};
  const BakeConfig whole_sun = settledBakeConfig(config);
  EXPECT_FALSE(whole_sun.scene_ranges.sun_zenith_deg.has_value());
  ASSERT_TRUE(whole_sun.scene_ranges.altitude_m.has_value());
  EXPECT_GE((*whole_sun.scene_ranges.altitude_m)[1], 15000.0);
  ASSERT_TRUE(whole_sun.sizes.iteration.has_value());
  EXPECT_EQ((*whole_sun.sizes.iteration)[2], config.sizes.scattering_mu_s);
  EXPECT_EQ(whole_sun.sizes.scattering_mu_s, config.sizes.scattering_mu_s);
  const AtmosphereDomain d = sceneDomain(whole_sun);
  EXPECT_EQ(d.scattering_mu_s_coord_min, 0.0);
  EXPECT_EQ(d.scattering_mu_s_coord_max, 1.0);

  config.scene_ranges.sun_zenith_deg = std::array<double, 2>{0.0, 90.0};
  const BakeConfig narrow_sun = settledBakeConfig(config);
  EXPECT_EQ(narrow_sun.scene_ranges.sun_zenith_deg, config.scene_ranges.sun_zenith_deg);
  ASSERT_TRUE(narrow_sun.sizes.iteration.has_value());
  EXPECT_EQ((*narrow_sun.sizes.iteration)[2], config.sizes.scattering_mu_s);
  EXPECT_LT(narrow_sun.sizes.scattering_mu_s, config.sizes.scattering_mu_s);

  // An explicit iteration is kept; a config that narrows nothing is unchanged.
  config.sizes.iteration = std::array<int, 4>{16, 64, 16, 4};
  EXPECT_EQ(*settledBakeConfig(config).sizes.iteration, *config.sizes.iteration);
  BakeConfig plain = builtinEarthConfig();
  EXPECT_FALSE(settledBakeConfig(plain).sizes.iteration.has_value());
  plain.scene_ranges.sun_zenith_deg = std::array<double, 2>{0.0, 110.0};
  EXPECT_FALSE(settledBakeConfig(plain).scene_ranges.sun_zenith_deg.has_value());
  EXPECT_FALSE(settledBakeConfig(plain).sizes.iteration.has_value());
}

}  // namespace
}  // namespace skybake
