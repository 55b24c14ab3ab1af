// The stress matrix's invariant checkers must be able to fail: a NaN, an
// infinity or a negative texel, a transmittance outside [0, 1] or rising
// along a ray, orders that grow, a jump between neighbouring lookups and an
// energy budget that does not close are each reported, with the worst
// offender named.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "baker/stress/invariants.h"
#include "baker/stress/stress_matrix.h"

namespace skybake {
namespace {

constexpr int kChannels = 3;

std::vector<Spectrum> goodTexels() { return std::vector<Spectrum>(16, Spectrum(0.5f, 1.0f, 0.0f, 0.0f)); }

TEST(Invariants, FiniteNonNegativeTexelsPassOnAGoodTable) {
  const InvariantResult r = checkFiniteNonNegativeTexels("t", goodTexels(), kChannels);
  EXPECT_TRUE(r.passed());
  EXPECT_EQ(r.checked, 16);
}

TEST(Invariants, ATexelWithANaNFails) {
  std::vector<Spectrum> texels = goodTexels();
  texels[7][1] = std::numeric_limits<float>::quiet_NaN();
  const InvariantResult r = checkFiniteNonNegativeTexels("t", texels, kChannels);
  EXPECT_FALSE(r.passed());
  EXPECT_EQ(r.failed, 1);
  EXPECT_NE(r.worst.find("texel 7"), std::string::npos) << r.worst;
  EXPECT_TRUE(std::isinf(r.worst_excess));
}

TEST(Invariants, AnInfiniteOrNegativeTexelFailsAndTheWorstIsNamed) {
  std::vector<Spectrum> texels = goodTexels();
  texels[2][0] = -1e-3f;
  texels[9][2] = -5.0f;
  const InvariantResult r = checkFiniteNonNegativeTexels("t", texels, kChannels);
  EXPECT_EQ(r.failed, 2);
  EXPECT_NE(r.worst.find("texel 9"), std::string::npos) << r.worst;
  EXPECT_DOUBLE_EQ(r.worst_excess, 5.0);

  texels = goodTexels();
  texels[3][0] = std::numeric_limits<float>::infinity();
  EXPECT_FALSE(checkFiniteNonNegativeTexels("t", texels, kChannels).passed());
}

TEST(Invariants, UnusedLanesAreNotChecked) {
  std::vector<Spectrum> texels = goodTexels();
  texels[0][3] = std::numeric_limits<float>::quiet_NaN();  // lane 3 beyond kChannels
  EXPECT_TRUE(checkFiniteNonNegativeTexels("t", texels, kChannels).passed());
}

TEST(Invariants, TransmittanceOutsideTheUnitIntervalFails) {
  InvariantResult r("transmittance");
  checkUnitInterval(r, Spectrum(0.0f, 1.0f, 0.3f, 0.0f), kChannels, "ok");
  EXPECT_TRUE(r.passed());
  checkUnitInterval(r, Spectrum(0.5f, 1.01f, 0.3f, 0.0f), kChannels, "above");
  checkUnitInterval(r, Spectrum(0.5f, 0.5f, -0.1f, 0.0f), kChannels, "below");
  checkUnitInterval(r, Spectrum(std::nanf(""), 0.5f, 0.5f, 0.0f), kChannels, "nan");
  EXPECT_EQ(r.failed, 3);
  EXPECT_EQ(r.checked, 4);
  EXPECT_NE(r.worst.find("nan"), std::string::npos) << r.worst;
}

TEST(Invariants, TransmittanceThatIncreasesAlongARayIsCaught) {
  InvariantResult r("monotone");
  checkNonIncreasing(r, {Spectrum(1.0f), Spectrum(0.8f), Spectrum(0.8f), Spectrum(0.1f)}, kChannels, "falling");
  EXPECT_TRUE(r.passed());
  checkNonIncreasing(r, {Spectrum(1.0f), Spectrum(0.0f), Spectrum(0.017f, 0.0f, 0.0f, 0.0f)}, kChannels, "rising");
  EXPECT_FALSE(r.passed());
  EXPECT_NE(r.worst.find("rising, step 2 ch0"), std::string::npos) << r.worst;
}

TEST(Invariants, TransmittanceRoundingWithinTheToleranceIsNotARise) {
  InvariantResult r("monotone");
  const float t = 0.5f;
  checkNonIncreasing(r, {Spectrum(t), Spectrum(t * float(1.0 + 0.5 * kTransmittanceRiseTolerance))}, kChannels, "ok");
  EXPECT_TRUE(r.passed());
  checkNonIncreasing(r, {Spectrum(t), Spectrum(t * float(1.0 + 10.0 * kTransmittanceRiseTolerance))}, kChannels, "x");
  EXPECT_FALSE(r.passed());
}

TEST(Invariants, GrowingOrdersFailFromTheThirdOrderOn) {
  auto order = [](int n, float radiance) { return OrderContribution{n, Spectrum(radiance), Spectrum(0.0f)}; };
  // Order 2 above order 1 is allowed (weak single scattering).
  EXPECT_TRUE(
      checkOrdersDecrease({order(1, 1.0f), order(2, 2.0f), order(3, 1.0f), order(4, 0.5f)}, kChannels).passed());
  const InvariantResult r = checkOrdersDecrease({order(1, 1.0f), order(2, 0.5f), order(3, 0.6f)}, kChannels);
  EXPECT_FALSE(r.passed());
  EXPECT_NE(r.worst.find("order 3"), std::string::npos) << r.worst;
  // No atmosphere: every order 0, which is not growth.
  EXPECT_TRUE(checkOrdersDecrease({order(1, 0.0f), order(2, 0.0f), order(3, 0.0f)}, kChannels).passed());
  EXPECT_FALSE(checkOrdersDecrease({order(1, 0.0f), order(2, 0.0f), order(3, std::nanf(""))}, kChannels).passed());
}

TEST(Invariants, AJumpBetweenNeighbouringLookupsFails) {
  InvariantResult r("continuity");
  const double floor = 0.01;
  checkContinuous(r, Spectrum(0.99f), Spectrum(1.0f), Spectrum(1.01f), floor, kChannels, "smooth");
  // Tiny values: compared against the floor, not against themselves.
  checkContinuous(r, Spectrum(0.0f), Spectrum(1e-4f), Spectrum(2e-4f), floor, kChannels, "near zero");
  // A steep slope: 7 % per step, 6.5 % the step before.
  checkContinuous(r, Spectrum(1.07f), Spectrum(1.0f), Spectrum(0.93f), floor, kChannels, "steep");
  EXPECT_TRUE(r.passed());
  checkContinuous(r, Spectrum(0.0788f), Spectrum(0.0788f), Spectrum(0.0f), floor, kChannels, "jump");
  EXPECT_FALSE(r.passed());
  EXPECT_NEAR(r.worst_excess, 1.0, 1e-6);
  // 7 % after a flat step is a jump too.
  checkContinuous(r, Spectrum(1.0f), Spectrum(1.0f), Spectrum(0.93f), floor, kChannels, "step");
  checkContinuous(r, Spectrum(1.0f), Spectrum(1.0f), Spectrum(std::nanf("")), floor, kChannels, "nan");
  EXPECT_EQ(r.failed, 3);
}

TEST(Invariants, FiniteNonNegativeValuesRejectNaNAndNegatives) {
  InvariantResult r("radiance");
  checkFiniteNonNegative(r, Spectrum(0.0f, 2.0f, 3.0f, -1.0f), kChannels, "ok");  // lane 3 unused
  EXPECT_TRUE(r.passed());
  checkFiniteNonNegative(r, Spectrum(0.0f, -2.0f, 3.0f, 0.0f), kChannels, "negative");
  checkFiniteNonNegative(r, Spectrum(std::numeric_limits<float>::infinity()), kChannels, "inf");
  EXPECT_EQ(r.failed, 2);
}

EnergyBudget budgetWithOut(double diffuse_share) {
  EnergyBudget b;
  b.power_in_W_per_nm = SpectrumD(100.0, 100.0, 100.0, 0.0);
  b.diffuse_out_W_per_nm = SpectrumD(100.0 * diffuse_share, 99.0, 60.0, 0.0);
  b.direct_out_W_per_nm = SpectrumD(0.0, 0.0, 0.0, 0.0);
  b.ground_absorbed_W_per_nm = SpectrumD(0.0, 0.0, 40.0, 0.0);
  return b;
}

TEST(Invariants, AnEnergyBudgetThatDoesNotCloseFails) {
  EXPECT_TRUE(checkEnergyBudget(budgetWithOut(1.0), kChannels, kEnergyBudgetTolerance).passed());
  // 5 % of the light made (out > in) or lost both fail, the worst named.
  InvariantResult r = checkEnergyBudget(budgetWithOut(1.05), kChannels, kEnergyBudgetTolerance);
  EXPECT_EQ(r.failed, 1);
  EXPECT_NE(r.worst.find("ch0"), std::string::npos) << r.worst;
  EXPECT_NEAR(r.worst_excess, 0.05 - kEnergyBudgetTolerance, 1e-12);
  EXPECT_FALSE(checkEnergyBudget(budgetWithOut(0.95), kChannels, kEnergyBudgetTolerance).passed());
  EXPECT_FALSE(checkEnergyBudget(budgetWithOut(std::nan("")), kChannels, kEnergyBudgetTolerance).passed());
}

TEST(Invariants, AnEnergyBudgetThatMovesWithTheQuadratureFails) {
  EXPECT_TRUE(checkEnergyBudgetQuadrature(budgetWithOut(1.0), budgetWithOut(1.0005), kChannels).passed());
  const InvariantResult r = checkEnergyBudgetQuadrature(budgetWithOut(1.0), budgetWithOut(1.01), kChannels);
  EXPECT_FALSE(r.passed());
  EXPECT_NE(r.worst.find("ch0"), std::string::npos) << r.worst;
}

// A row fails on an unexpected failure, passes on a listed known failure, and
// a refusal passes only with a message in the usual "<where>: <key> = <value>:
// <reason>" shape.
TEST(Invariants, StressRowPassesOnlyOnPassedOrKnownFailures) {
  StressRow row;
  InvariantResult failing("orders decrease");
  failing.fail(1.0, "order 5");
  row.invariants = {InvariantResult("other"), failing};
  EXPECT_FALSE(row.passed());
  row.known_failures = {"orders decrease"};
  EXPECT_TRUE(row.passed());

  StressRow refused;
  refused.refused = "case: planet.bottom_radius_m = 0.5: must be in [1, 1e+10]";
  EXPECT_TRUE(refused.passed());
  refused.refused = "something went wrong";
  EXPECT_FALSE(refused.passed());
}

}  // namespace
}  // namespace skybake
