// Quadrature along rays through optically thick media.
#include "runtime/physics/ray_quadrature.h"

#include <cmath>

#include <gtest/gtest.h>

#include "data_formats/spectra/spectrum.h"

namespace skybake {
namespace {

// Fog: a uniform extinction of 1e-2 m^-1 (100 m mean free path) over 60 km,
// 3.75 km per sub-interval: an optical depth of 37.5 per sub-interval.
constexpr double kFogExtinction_per_m = 1e-2;
constexpr double kFogLength_m = 60000.0;
constexpr int kSegments = 16;

// Light scattered at every point of the fog and attenuated back to the
// start: integral of sigma exp(-sigma t) = 1 - exp(-600) = 1.
double fogIntegrand(double t) { return kFogExtinction_per_m * std::exp(-kFogExtinction_per_m * t); }

TEST(RayQuadrature, FixedSubintervalsMissThickFog) {
  // Guards the test below: without splitting, the 4-point rule on tau in
  // [0, 37.5] puts its first node at tau 2.6 and misses half the light.
  double sum = 0.0;
  forEachQuadratureNode(0.0, kFogLength_m, kSegments, [&](double t, double w) { sum += fogIntegrand(t) * w; });
  EXPECT_LT(sum, 0.6);
}

TEST(RayQuadrature, ThickSubintervalsAreSplit) {
  double sum = 0.0;
  int nodes = 0;
  forEachOpticallyThinNode(
      0.0, kFogLength_m, kSegments, 0.0, [](double) { return kFogExtinction_per_m; },
      [&](double t, double w) {
        sum += fogIntegrand(t) * w;
        ++nodes;
      });
  // Pieces of optical depth 3 (3e-6 relative each, ray_quadrature.h) up to an
  // optical depth of 40, beyond which less than e^-40 of the light remains.
  EXPECT_NEAR(sum, 1.0, 1e-5);
  // Work is bounded: 14 pieces reach depth 40, then one piece per remaining
  // sub-interval (plus the rest of the first).
  EXPECT_LE(nodes, kGaussNodes * (14 + kSegments + 1));
}

TEST(RayQuadrature, ThinRaysKeepTheFixedRule) {
  // Earth's longest ray holds an optical depth of about 2 per sub-interval:
  // the nodes must be those of the fixed rule (bakes of clear air unchanged).
  constexpr double kClearAir_per_m = 3.8e-5;
  std::vector<double> fixed, thin;
  forEachQuadratureNode(0.0, 875e3, kSegments, [&](double t, double) { fixed.push_back(t); });
  forEachOpticallyThinNode(
      0.0, 875e3, kSegments, 0.0, [](double) { return kClearAir_per_m; }, [&](double t, double) { thin.push_back(t); });
  ASSERT_EQ(fixed.size(), thin.size());
  for (size_t i = 0; i < fixed.size(); ++i) EXPECT_NEAR(fixed[i], thin[i], 1e-6) << i;
}

TEST(RayQuadrature, IntegralToEachNodeIsTheOpticalDepth) {
  // Fog whose extinction grows with distance: tau(t) = sigma t + k t^2 / 2.
  constexpr double kGrowth_per_m2 = 1e-7;
  auto extinction = [](double t) { return SpectrumD(kFogExtinction_per_m + kGrowth_per_m2 * t); };
  double sum = 0.0;
  forEachOpticallyThinNodeWithIntegral<SpectrumD>(
      kFogLength_m, kSegments, 0.0, extinction, largestChannel, [&](double t, double w, const SpectrumD& depth) {
        const double exact = kFogExtinction_per_m * t + 0.5 * kGrowth_per_m2 * t * t;
        // The partial integral is a 4-point rule on a polynomial of degree 1:
        // exact to rounding.
        EXPECT_NEAR(depth.x, exact, 1e-9 * (1.0 + exact)) << t;
        sum += extinction(t).x * std::exp(-depth.x) * w;
      });
  // Integral of tau'(t) exp(-tau(t)) = 1 - exp(-tau(L)) = 1.
  EXPECT_NEAR(sum, 1.0, 1e-5);
}

TEST(RayQuadrature, NonFiniteExtinctionDoesNotLoop) {
  int nodes = 0;
  forEachOpticallyThinNode(
      0.0, 1000.0, kSegments, 0.0, [](double) { return INFINITY; }, [&](double, double) { ++nodes; });
  EXPECT_EQ(nodes, kGaussNodes * kSegments);
}

}  // namespace
}  // namespace skybake
