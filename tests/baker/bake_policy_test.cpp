// Bake policy: which scene ranges a bake narrows its tables to, and the
// sizes its orders iterate on.
#include <gtest/gtest.h>

#include "baker/bake/bake_policy.h"
#include "data_formats/config.h"
#include "data_formats/texture_mapping.h"

namespace skybake {
namespace {

// A sun range that would not make the sun axis a texel finer is dropped
// (0 to 100 deg plus the margin is 99.7 % of Earth's 0 to 102 deg axis: a
// tenth of a texel at 32); one that does (0 to 90 deg, about 14 texels) stays.
// Either way a narrowed bake gets its iteration sizes written out, with the
// stored mu_s where the sun axis is whole and that is larger than the default.
TEST(BakePolicy, SettledConfigKeepsOnlySunRangesThatNarrowTheAxis) {
  BakeConfig config = builtinEarthConfig();
  config.scene_ranges.altitude_m = std::array<double, 2>{0.0, 15000.0};
  config.scene_ranges.sun_zenith_deg = std::array<double, 2>{0.0, 100.0};
  config.sizes.scattering_mu_s = 40;
  const BakeConfig whole_sun = settledBakeConfig(config);
  EXPECT_FALSE(whole_sun.scene_ranges.sun_zenith_deg.has_value());
  EXPECT_EQ(whole_sun.scene_ranges.altitude_m, config.scene_ranges.altitude_m);
  ASSERT_TRUE(whole_sun.sizes.iteration.has_value());
  EXPECT_EQ(*whole_sun.sizes.iteration, (std::array<int, 4>{32, 128, 40, 8}));
  const AtmosphereDomain d = AtmosphereDomain::fromConfig(whole_sun);
  EXPECT_EQ(d.scattering_mu_s_coord_min, 0.0);
  EXPECT_EQ(d.scattering_mu_s_coord_max, 1.0);

  config.scene_ranges.sun_zenith_deg = std::array<double, 2>{0.0, 90.0};
  const BakeConfig narrow_sun = settledBakeConfig(config);
  EXPECT_EQ(narrow_sun.scene_ranges.sun_zenith_deg, config.scene_ranges.sun_zenith_deg);
  ASSERT_TRUE(narrow_sun.sizes.iteration.has_value());
  EXPECT_EQ(*narrow_sun.sizes.iteration, (std::array<int, 4>{32, 128, 32, 8}));

  // An explicit iteration is kept; a config that narrows nothing is unchanged.
  config.sizes.iteration = std::array<int, 4>{16, 64, 16, 4};
  EXPECT_EQ(*settledBakeConfig(config).sizes.iteration, *config.sizes.iteration);
  BakeConfig plain = builtinEarthConfig();
  EXPECT_FALSE(settledBakeConfig(plain).sizes.iteration.has_value());
  plain.scene_ranges.sun_zenith_deg = std::array<double, 2>{0.0, 101.5};
  EXPECT_FALSE(settledBakeConfig(plain).scene_ranges.sun_zenith_deg.has_value());
  EXPECT_FALSE(settledBakeConfig(plain).sizes.iteration.has_value());
}

}  // namespace
}  // namespace skybake
