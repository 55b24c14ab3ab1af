// Bake policy: which scene ranges a bake narrows its tables to, and the
// sizes its orders iterate on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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

// A scene's ranges narrow the 4D axes: texels still round-trip, the r axis
// ends on the range's altitudes, and the sun axis covers the range plus its
// 1 deg margin with one texel on the horizon.
TEST(BakePolicy, NarrowedScatteringAxesRoundTripAndEndOnTheSceneRanges) {
  BakeConfig config = builtinEarthConfig();
  const AtmosphereDomain domain = AtmosphereDomain::fromParameters(config.atmosphere);
  const ScatteringSizes sizes = ScatteringSizes::fromTextureSizes(config.sizes);
  config.scene_ranges.altitude_m = std::array<double, 2>{500.0, 2000.0};
  config.scene_ranges.sun_zenith_deg = std::array<double, 2>{20.0, 90.0};
  const AtmosphereDomain narrow = sceneDomain(config);
  ASSERT_TRUE(narrow.narrowed());
  EXPECT_FALSE(domain.narrowed());
  // r comes back through sqrt(rho^2 + R^2) with R = 6.36e6 m: ~1e-9 m.
  EXPECT_NEAR(rFromScatteringTexel(narrow, sizes, 0), domain.bottom_radius_m + 500.0, 1e-6);
  EXPECT_NEAR(rFromScatteringTexel(narrow, sizes, sizes.r - 1), domain.bottom_radius_m + 2000.0, 1e-6);
  const double deg = radiansFromDegrees(1.0);
  EXPECT_NEAR(muSFromScatteringTexel(narrow, sizes, sizes.mu_s - 1), std::cos(19.0 * deg), 1e-9);
  // The low end moves down from 91 deg by less than one texel to put a
  // texel on the horizon.
  const double lowest_deg = std::acos(muSFromScatteringTexel(narrow, sizes, 0)) / deg;
  const double second_deg = std::acos(muSFromScatteringTexel(narrow, sizes, 1)) / deg;
  EXPECT_GE(lowest_deg, 91.0 - 1e-9);
  EXPECT_LT(lowest_deg - 91.0, lowest_deg - second_deg);
  double closest_to_horizon = 1.0;
  for (int i = 0; i < sizes.mu_s; ++i) {
    closest_to_horizon = std::min(closest_to_horizon, std::abs(muSFromScatteringTexel(narrow, sizes, i)));
  }
  EXPECT_LT(closest_to_horizon, 1e-9);
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

// A sun range that would not make the sun axis a texel finer is dropped
// (0 to 109 deg plus the 1 deg margin stops 1 deg short of Earth's 0 to
// 111 deg axis, under one of its 1.46 deg texels there); one that does (0
// to 90 deg, about 22 texels) stays.
// Either way a narrowed bake gets its iteration sizes written out, with the
// stored mu_s where the sun axis is whole and that is larger than the default.
TEST(BakePolicy, SettledConfigKeepsOnlySunRangesThatNarrowTheAxis) {
  BakeConfig config = builtinEarthConfig();
  config.scene_ranges.altitude_m = std::array<double, 2>{0.0, 15000.0};
  config.scene_ranges.sun_zenith_deg = std::array<double, 2>{0.0, 109.0};
  config.sizes.scattering_mu_s = 44;
  const BakeConfig whole_sun = settledBakeConfig(config);
  EXPECT_FALSE(whole_sun.scene_ranges.sun_zenith_deg.has_value());
  EXPECT_EQ(whole_sun.scene_ranges.altitude_m, config.scene_ranges.altitude_m);
  ASSERT_TRUE(whole_sun.sizes.iteration.has_value());
  EXPECT_EQ(*whole_sun.sizes.iteration, (std::array<int, 4>{32, 128, 44, 16}));
  const AtmosphereDomain d = sceneDomain(whole_sun);
  EXPECT_EQ(d.scattering_mu_s_coord_min, 0.0);
  EXPECT_EQ(d.scattering_mu_s_coord_max, 1.0);

  config.scene_ranges.sun_zenith_deg = std::array<double, 2>{0.0, 90.0};
  const BakeConfig narrow_sun = settledBakeConfig(config);
  EXPECT_EQ(narrow_sun.scene_ranges.sun_zenith_deg, config.scene_ranges.sun_zenith_deg);
  ASSERT_TRUE(narrow_sun.sizes.iteration.has_value());
  EXPECT_EQ(*narrow_sun.sizes.iteration, (std::array<int, 4>{32, 128, 41, 16}));

  // An explicit iteration is kept; a config that narrows nothing is unchanged.
  config.sizes.iteration = std::array<int, 4>{16, 64, 16, 4};
  EXPECT_EQ(*settledBakeConfig(config).sizes.iteration, *config.sizes.iteration);
  BakeConfig plain = builtinEarthConfig();
  EXPECT_FALSE(settledBakeConfig(plain).sizes.iteration.has_value());
  plain.scene_ranges.sun_zenith_deg = std::array<double, 2>{0.0, 107.5};
  EXPECT_FALSE(settledBakeConfig(plain).scene_ranges.sun_zenith_deg.has_value());
  EXPECT_FALSE(settledBakeConfig(plain).sizes.iteration.has_value());
}

}  // namespace
}  // namespace skybake
