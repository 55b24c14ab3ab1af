// Whole bakes at reduced sizes: orders converge, results do not depend on the
// thread count, and the values are physically sensible.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

#include <omp.h>
#include <unistd.h>

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
// the tolerance in every (altitude, sun) slice, and not before: the same bake
// capped one order earlier must still be above it (else the loop ran one
// order too many), and the report says so.
TEST(Bake, AutomaticOrdersStopWhenTheLastOrderIsBelowTheToleranceInEverySlice) {
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
  const OrdersDecision& decision = bake.report.orders_decision;
  EXPECT_TRUE(decision.converged);
  EXPECT_LT(decision.last_order_share, 1e-2f);
  // The table-mean share, from the report's per-order means.
  float mean_share = 0.0f;
  for (int c = 0; c < 3; ++c) {
    float total = 0.0f;
    for (const OrderContribution& o : orders) total += o.mean_radiance[c];
    mean_share = std::max(mean_share, orders.back().mean_radiance[c] / total);
  }
  EXPECT_FLOAT_EQ(decision.mean_last_order_share, mean_share);
  // A slice's share can only be at least the mean's somewhere: the worst
  // slice bounds the mean share from above.
  EXPECT_GE(decision.last_order_share, mean_share);

  BakeConfig one_less = config;
  one_less.bake.max_orders = static_cast<int>(orders.size()) - 1;
  const BakeOutput earlier = bakeAtmosphere(one_less, 0, silent);
  EXPECT_FALSE(earlier.report.orders_decision.converged);
  EXPECT_GE(earlier.report.orders_decision.last_order_share, 1e-2f);

  // A cap below what convergence needs: stops at the cap, reported unconverged.
  config.bake.max_orders = 2;
  const BakeOutput capped = bakeAtmosphere(config, 0, silent);
  EXPECT_EQ(capped.file.orders_computed, 2);
  EXPECT_FALSE(capped.report.orders_decision.converged);
}

// The orders converge slowest in the planet's shadow, where the light has
// scattered many times: with 4 orders the worst slice is deep in twilight
// (sun at least 100 deg from the zenith, near the ground), and there the
// fourth order's share is several times its share of the whole table's mean.
TEST(Bake, OrdersConvergeSlowestInDeepTwilight) {
  SilentProgress silent;
  const BakeOutput bake = bakeAtmosphere(test::smallEarth(4), 0, silent);
  const OrdersDecision& decision = bake.report.orders_decision;
  EXPECT_GE(decision.worst_sun_zenith_deg, 100.0);
  EXPECT_LT(decision.worst_altitude_m, 10e3);
  EXPECT_GT(decision.last_order_share, 3.0f * decision.mean_last_order_share);
}

TEST(Bake, TablesAreFiniteAndNonNegative) {
  SilentProgress silent;
  const BakeOutput bake = bakeAtmosphere(test::smallEarth(3), 0, silent);
  const BakeTables& t = bake.file.tables;
  for (const auto* texels : {&t.optical_depth.texels, &t.irradiance.texels, &t.single_rayleigh.texels,
                             &t.single_mie.texels, &t.multiple_scattering.texels, &t.multiple_density.texels}) {
    for (const Spectrum& s : *texels) {
      for (int c = 0; c < 4; ++c) {
        ASSERT_TRUE(std::isfinite(s[c]));
        ASSERT_GE(s[c], 0.0f);
      }
    }
  }
}

// Determinism: every table, and the whole written file of a reproducible
// bake, byte for byte. The tables are walked with forEachTable, so a table
// added to the bake is compared without this test changing.
TEST(Bake, ResultIsIdenticalForOneAndTwoThreads) {
  SilentProgress silent;
  const BakeConfig config = test::smallEarth(3);
  BakeOutput one = bakeAtmosphere(config, 1, silent);
  BakeOutput two = bakeAtmosphere(config, 2, silent);
  std::vector<std::pair<std::string, const std::vector<Spectrum>*>> tables_one, tables_two;
  forEachTable(one.file.tables, [&](const char* part, const auto& texels) { tables_one.emplace_back(part, &texels); });
  forEachTable(two.file.tables, [&](const char* part, const auto& texels) { tables_two.emplace_back(part, &texels); });
  ASSERT_EQ(tables_one.size(), 6u);
  for (size_t i = 0; i < tables_one.size(); ++i) {
    const std::vector<Spectrum>& a = *tables_one[i].second;
    const std::vector<Spectrum>& b = *tables_two[i].second;
    EXPECT_FALSE(a.empty()) << tables_one[i].first;
    EXPECT_TRUE(a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Spectrum)) == 0)
        << tables_one[i].first << " differs between 1 and 2 threads";
  }
  setStoredReport(one, false);
  setStoredReport(two, false);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("skybake_determinism_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  writeBakeFile(dir / "one.exr", one.file);
  writeBakeFile(dir / "two.exr", two.file);
  auto bytes = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string file_one = bytes(dir / "one.exr");
  EXPECT_FALSE(file_one.empty());
  EXPECT_TRUE(file_one == bytes(dir / "two.exr")) << "the written files differ between 1 and 2 threads";
  std::filesystem::remove_all(dir);
}

// The channels may come in any order: each is named in the file by its
// wavelength, and the image and lookup code find channels by wavelength, not
// by position. A bake of the same atmosphere with its channels listed in
// another order holds, channel by channel, the same tables. Bit-identical,
// since every operation on a Spectrum acts on each channel alone and with
// a fixed order count nothing compares channels.
TEST(Bake, ChannelOrderDoesNotChangeAnyChannel) {
  SilentProgress silent;
  const BakeConfig sorted = test::smallEarth(2);
  ASSERT_EQ(sorted.atmosphere.wavelengths_nm, (std::vector<double>{680.0, 550.0, 440.0}));
  BakeConfig shuffled = sorted;
  const int from[3] = {2, 0, 1};  // shuffled channel c is sorted channel from[c]
  auto permute = [&](Spectrum& s) {
    const Spectrum old = s;
    for (int c = 0; c < 3; ++c) s[c] = old[from[c]];
  };
  AtmosphereParameters& a = shuffled.atmosphere;
  for (int c = 0; c < 3; ++c) a.wavelengths_nm[c] = sorted.atmosphere.wavelengths_nm[from[c]];
  for (Spectrum* s : {&a.ground_albedo, &a.sun_irradiance, &a.rayleigh_scattering, &a.mie_scattering, &a.mie_extinction,
                      &a.absorption_extinction}) {
    permute(*s);
  }
  const BakeOutput one = bakeAtmosphere(sorted, 0, silent);
  const BakeOutput two = bakeAtmosphere(shuffled, 0, silent);
  std::vector<std::pair<std::string, const std::vector<Spectrum>*>> tables_one, tables_two;
  forEachTable(one.file.tables, [&](const char* part, const auto& texels) { tables_one.emplace_back(part, &texels); });
  forEachTable(two.file.tables, [&](const char* part, const auto& texels) { tables_two.emplace_back(part, &texels); });
  ASSERT_EQ(tables_one.size(), tables_two.size());
  for (size_t i = 0; i < tables_one.size(); ++i) {
    const std::vector<Spectrum>& a_texels = *tables_one[i].second;
    const std::vector<Spectrum>& b_texels = *tables_two[i].second;
    ASSERT_EQ(a_texels.size(), b_texels.size());
    size_t differing = 0;
    for (size_t t = 0; t < a_texels.size(); ++t) {
      for (int c = 0; c < 3; ++c) differing += b_texels[t][c] != a_texels[t][from[c]];
    }
    EXPECT_EQ(differing, 0u) << tables_one[i].first;
  }
}

// A bake that asks for a thread count leaves OpenMP's setting as it found
// it: a later bake asking for OpenMP's default (0) gets that default, not
// the earlier bake's count.
TEST(Bake, LeavesTheOpenMpThreadCountAsItFoundIt) {
  SilentProgress silent;
  const int before = omp_get_max_threads();
  omp_set_num_threads(3);
  const BakeConfig config = test::smallEarth(1);
  EXPECT_EQ(bakeAtmosphere(config, 1, silent).report.threads, 1);
  EXPECT_EQ(omp_get_max_threads(), 3);
  EXPECT_EQ(bakeAtmosphere(config, 0, silent).report.threads, 3);
  omp_set_num_threads(before);
}

// A channel in which nothing scatters adds no light in any order. The tail
// estimate then leaves that channel at 0 and applies to the others, and its
// reason never prints a ratio of zeros (0 / 0 printed "nan").
TEST(Bake, TailEstimateSkipsAChannelInWhichNothingScatters) {
  SilentProgress silent;
  BakeConfig config = test::smallEarth(3);
  config.atmosphere.rayleigh_scattering[1] = 0.0f;
  config.atmosphere.mie_scattering[1] = 0.0f;
  const BakeOutput bake = bakeAtmosphere(config, 0, silent);
  for (const OrderContribution& o : bake.report.orders) EXPECT_EQ(o.mean_radiance[1], 0.0f) << "order " << o.order;
  EXPECT_TRUE(bake.report.tail.applied) << bake.report.tail.reason;
  EXPECT_EQ(bake.report.tail.ratio[1], 0.0f);
  EXPECT_GT(bake.report.tail.ratio[0], 0.0f);
  EXPECT_GT(bake.report.tail.ratio[2], 0.0f);
  EXPECT_EQ(bake.report.tail.reason.find("nan"), std::string::npos) << bake.report.tail.reason;
  EXPECT_EQ(bake.report.tail.reason.find("inf"), std::string::npos) << bake.report.tail.reason;
}

}  // namespace
}  // namespace skybake
