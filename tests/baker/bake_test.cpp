// Whole bakes at reduced sizes: orders converge, results do not depend on the
// thread count, and the values are physically sensible.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "baker/bake.h"
#include "test_configs.h"

namespace skybake {
namespace {

TEST(Bake, EachOrderAddsLessThanThePrevious) {
  SilentProgress silent;
  const BakeOutput bake = bakeAtmosphere(test::smallEarth(5), 0, silent);
  const std::vector<OrderContribution>& orders = bake.report.orders;
  ASSERT_EQ(orders.size(), 5u);
  for (size_t i = 1; i < orders.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_GT(orders[i].mean_radiance[c], 0.0f) << "order " << orders[i].order;
      EXPECT_LT(orders[i].mean_radiance[c], orders[i - 1].mean_radiance[c]) << "order " << orders[i].order;
      if (i + 1 < orders.size()) {
        EXPECT_GT(orders[i].mean_irradiance[c], 0.0f);
        EXPECT_LT(orders[i].mean_irradiance[c], orders[i - 1].mean_irradiance[c]);
      }
    }
  }
  // Earth's sky is optically thin: beyond the second order each order is well
  // under half the previous one (the single-scattering albedo times the mean
  // escape probability is below 0.5 at every channel).
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(orders[3].mean_radiance[c], 0.5f * orders[2].mean_radiance[c]);
  }
}

TEST(Bake, TablesAreFiniteAndNonNegative) {
  SilentProgress silent;
  const BakeOutput bake = bakeAtmosphere(test::smallEarth(3), 0, silent);
  const BakeTables& t = bake.file.tables;
  for (const auto* texels : {&t.transmittance.texels, &t.irradiance.texels, &t.scattering.texels, &t.single_mie.texels,
                             &t.multiple_density.texels}) {
    for (const Spectrum& s : *texels) {
      for (int c = 0; c < 4; ++c) {
        ASSERT_TRUE(std::isfinite(s[c]));
        ASSERT_GE(s[c], 0.0f);
      }
    }
  }
}

TEST(Bake, ResultIsIdenticalForOneAndTwoThreads) {
  SilentProgress silent;
  const BakeConfig config = test::smallEarth(3);
  const BakeOutput one = bakeAtmosphere(config, 1, silent);
  const BakeOutput two = bakeAtmosphere(config, 2, silent);
  auto identical = [](const std::vector<Spectrum>& a, const std::vector<Spectrum>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Spectrum)) == 0;
  };
  EXPECT_TRUE(identical(one.file.tables.transmittance.texels, two.file.tables.transmittance.texels));
  EXPECT_TRUE(identical(one.file.tables.irradiance.texels, two.file.tables.irradiance.texels));
  EXPECT_TRUE(identical(one.file.tables.scattering.texels, two.file.tables.scattering.texels));
  EXPECT_TRUE(identical(one.file.tables.single_mie.texels, two.file.tables.single_mie.texels));
  EXPECT_TRUE(identical(one.file.tables.multiple_density.texels, two.file.tables.multiple_density.texels));
}

}  // namespace
}  // namespace skybake
