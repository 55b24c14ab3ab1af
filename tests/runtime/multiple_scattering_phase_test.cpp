#include "runtime/physics/multiple_scattering_phase.h"

#include <gtest/gtest.h>

#include <cmath>

#include "data_formats/config/config.h"

namespace skybake {
namespace {

// Integral of f over the sphere by the midpoint rule in nu (f depends on nu
// only): 20000 pieces integrate the g_ms = 0.64 peak to ~1e-6.
double integralOverSphere(const MultipleScatteringPhase& shape, const SpectrumD& weight, int channel) {
  constexpr int kPieces = 20000;
  double sum = 0.0;
  for (int i = 0; i < kPieces; ++i) {
    const double nu = -1.0 + (i + 0.5) * 2.0 / kPieces;
    sum += shape(weight, nu)[channel] * 2.0 * kPi * (2.0 / kPieces);
  }
  return sum;
}

TEST(MultipleScatteringPhase, IsNormalisedLikeAPhaseFunctionForAnyWeight) {
  const MultipleScatteringPhase shape(builtinEarthConfig().atmosphere);
  for (double w : {0.0, 0.3, 1.0}) {
    // float texels: 1e-5 relative.
    EXPECT_NEAR(integralOverSphere(shape, SpectrumD(w), 0), 1.0, 1e-5) << "weight " << w;
  }
}

TEST(MultipleScatteringPhase, PeakWeightIsTheLocalMieShareTimesTheColumnsSquaredThinnedByScatteringDepth) {
  AtmosphereParameters a = builtinEarthConfig().atmosphere;
  const MultipleScatteringPhase shape(a);
  const MultipleScatteringPhase version7_shape(a, kStoredShapeOrder, MultipleShapeWeight::ColumnShare);
  // Exponential profiles from 0 to the top (60 km): column = H (1 - exp(-top / H)).
  const double top_m = a.top_radius_m - a.bottom_radius_m;
  const double rayleigh_h = 8000.0, mie_h = 1200.0;  // the built-in Earth's scale heights
  for (int c = 0; c < 3; ++c) {
    const double beta_r = a.rayleigh_scattering[c], beta_m = a.mie_scattering[c];
    const double tau_r = beta_r * rayleigh_h * (1.0 - std::exp(-top_m / rayleigh_h));
    const double tau_m = beta_m * mie_h * (1.0 - std::exp(-top_m / mie_h));
    const double column = tau_m / (tau_m + tau_r);
    const double local = beta_m / (beta_m + beta_r);  // at the ground, both densities 1
    const double thinning = 1.0 - (tau_r + tau_m);
    // The midpoint rule's pieces are 15 m against a 1200 m scale height:
    // relative error (15 / 1200)^2 / 24 ~ 7e-6; 1e-4 leaves room.
    const double expected = local * column * column * thinning;
    EXPECT_NEAR(shape.peakWeightAt(0.0)[c], expected, 1e-4 * expected) << c;
    EXPECT_NEAR(version7_shape.peakWeightAt(0.0)[c], local * column * column, 1e-4 * local * column * column) << c;
  }
  // At 10 km Mie's density is exp(-10000 / 1200) of the ground's: the weight
  // falls with it (the divisor turns broad above the haze).
  EXPECT_LT(shape.peakWeightAt(10000.0)[0], 0.01 * shape.peakWeightAt(0.0)[0]);
}

TEST(MultipleScatteringPhase, HigherOrdersHaveWiderAndWeakerPeaks) {
  AtmosphereParameters a = builtinEarthConfig().atmosphere;
  a.mie_scattering *= 100.0f;  // a haze, so the peak weights are far from 0
  a.mie_extinction *= 100.0f;
  const MultipleScatteringPhase second(a), third(a, 3);
  EXPECT_EQ(second.order(), kStoredShapeOrder);
  EXPECT_DOUBLE_EQ(third.g(), 0.8 * 0.8 * 0.8);
  for (int c = 0; c < 3; ++c) {
    // One more factor of the column's Mie share, which is below 1.
    const double ratio = third.peakWeightAt(0.0)[c] / second.peakWeightAt(0.0)[c];
    EXPECT_GT(ratio, 0.5) << c;
    EXPECT_LT(ratio, 1.0) << c;
  }
  // Two backward Mie scatterings make a forward peak, three a backward one.
  a.mie_phase_g = -0.6;
  EXPECT_GT(MultipleScatteringPhase(a, 2).g(), 0.0);
  EXPECT_LT(MultipleScatteringPhase(a, 3).g(), 0.0);
}

TEST(MultipleScatteringPhase, NothingScatteringGivesTheIsotropicShape) {
  AtmosphereParameters a = builtinEarthConfig().atmosphere;
  a.rayleigh_scattering = Spectrum(0.0f);
  a.mie_scattering = Spectrum(0.0f);
  const MultipleScatteringPhase shape(a);
  for (double nu : {-1.0, 0.0, 1.0}) {
    const Spectrum f = shape(0.0, nu);
    EXPECT_FLOAT_EQ(f[0], static_cast<float>(1.0 / (4.0 * kPi))) << nu;
  }
}

TEST(MultipleScatteringPhase, AColumnThickerThanOneScatteringDepthHasNoPeak) {
  AtmosphereParameters a = builtinEarthConfig().atmosphere;
  a.mie_scattering *= 1000.0f;  // a vertical Mie scattering depth of several
  a.mie_extinction *= 1000.0f;
  for (int order : {2, 3}) {
    const MultipleScatteringPhase shape(a, order);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(shape.peakWeightAt(0.0)[c], 0.0) << order << " " << c;
      // The divisor is the broad part alone, never 0.
      EXPECT_FLOAT_EQ(shape(0.0, 1.0)[c], static_cast<float>(MultipleScatteringPhase::kBroad)) << order << " " << c;
    }
    // A version 7 file's shape keeps its peak.
    EXPECT_GT(MultipleScatteringPhase(a, order, MultipleShapeWeight::ColumnShare).peakWeightAt(0.0)[0], 0.1);
  }
}

TEST(MultipleScatteringPhase, PeakIsClampedForNearlyDeltaMie) {
  AtmosphereParameters a = builtinEarthConfig().atmosphere;
  a.mie_phase_g = 0.99;  // g^2 = 0.98
  EXPECT_DOUBLE_EQ(MultipleScatteringPhase(a).g(), kMaxMultipleScatteringG);
  a.mie_phase_g = -0.9;  // two backward scatterings make a forward peak: g^2 > 0
  EXPECT_DOUBLE_EQ(MultipleScatteringPhase(a).g(), kMaxMultipleScatteringG);
  a.mie_phase_g = 0.5;
  EXPECT_DOUBLE_EQ(MultipleScatteringPhase(a).g(), 0.25);
}

}  // namespace
}  // namespace skybake
