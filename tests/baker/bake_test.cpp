// Whole bakes at reduced sizes: orders converge, results do not depend on the
// thread count, and the values are physically sensible.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "baker/bake/bake.h"
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

// Automatic orders stop at the first order whose share of the total is under
// the tolerance, and not before: the order before it must still be above it
// (else the loop ran one order too many), and the report says so.
TEST(Bake, AutomaticOrdersStopWhenTheLastOrderIsBelowTheTolerance) {
  SilentProgress silent;
  BakeConfig config = test::smallEarth(4);
  config.bake.auto_orders = true;
  config.bake.order_tolerance = 1e-2;
  config.bake.max_orders = 40;
  const BakeOutput bake = bakeAtmosphere(config, 0, silent);
  const std::vector<OrderContribution>& orders = bake.report.orders;
  ASSERT_GE(orders.size(), 3u);
  ASSERT_LT(orders.size(), 40u) << "Earth converges to 1 % long before 40 orders";
  EXPECT_EQ(bake.file.orders_computed, static_cast<int>(orders.size()));
  EXPECT_TRUE(bake.report.orders_decision.converged);
  auto share = [&](size_t last) {
    float worst = 0.0f;
    for (int c = 0; c < 3; ++c) {
      float total = 0.0f;
      for (size_t i = 0; i <= last; ++i) total += orders[i].mean_radiance[c];
      worst = std::max(worst, orders[last].mean_radiance[c] / total);
    }
    return worst;
  };
  EXPECT_LT(share(orders.size() - 1), 1e-2f);
  EXPECT_GE(share(orders.size() - 2), 1e-2f);
  EXPECT_FLOAT_EQ(bake.report.orders_decision.last_order_share, share(orders.size() - 1));

  // A cap below what convergence needs: stops at the cap, reported unconverged.
  config.bake.max_orders = 2;
  const BakeOutput capped = bakeAtmosphere(config, 0, silent);
  EXPECT_EQ(capped.file.orders_computed, 2);
  EXPECT_FALSE(capped.report.orders_decision.converged);
}

TEST(Bake, TablesAreFiniteAndNonNegative) {
  SilentProgress silent;
  const BakeOutput bake = bakeAtmosphere(test::smallEarth(3), 0, silent);
  const BakeTables& t = bake.file.tables;
  for (const auto* texels : {&t.transmittance.texels, &t.irradiance.texels, &t.single_rayleigh.texels, &t.single_mie.texels, &t.multiple_scattering.texels,
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
  EXPECT_TRUE(identical(one.file.tables.multiple_scattering.texels, two.file.tables.multiple_scattering.texels));
  EXPECT_TRUE(identical(one.file.tables.single_mie.texels, two.file.tables.single_mie.texels));
  EXPECT_TRUE(identical(one.file.tables.multiple_density.texels, two.file.tables.multiple_density.texels));
}

}  // namespace
}  // namespace skybake
