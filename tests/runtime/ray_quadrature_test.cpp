// Quadrature along rays through optically thick media.
#include "runtime/physics/ray_quadrature.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "data_formats/spectra/spectrum.h"
#include "runtime/physics/atmosphere_media.h"

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

// The pieces of a ray, as (start, end) pairs.
template <typename ExtinctionFn>
std::vector<std::pair<double, double>> piecesOf(double length_m, double lowest_t, ExtinctionFn extinction,
                                                double bound_per_m) {
  std::vector<std::pair<double, double>> pieces;
  forEachOpticallyThinPiece(
      0.0, length_m, kSegments, lowest_t, extinction, [&](double a, double b) { pieces.emplace_back(a, b); },
      bound_per_m);
  return pieces;
}

TEST(RayQuadrature, AnExtinctionBoundGivesThePiecesThePeaksGive) {
  // A layer whose extinction peaks mid-ray at 1e-4 m^-1, falling off over a
  // twelfth of the ray. Over 60 km that is 0.375 per sub-interval at the
  // peak: no splits, and the bound (the peak) must say so without changing a
  // piece or reading the extinction.
  int calls = 0;
  auto layer = [&](double length_m) {
    return [&calls, length_m](double t) {
      ++calls;
      return 1e-4 * std::exp(-std::abs(t - 0.5 * length_m) / (length_m / 12.0));
    };
  };
  const auto peaks = piecesOf(kFogLength_m, 0.0, layer(kFogLength_m), kNoExtinctionBound);
  calls = 0;
  const auto bounded = piecesOf(kFogLength_m, 0.0, layer(kFogLength_m), 1e-4);
  EXPECT_EQ(bounded, peaks);
  EXPECT_EQ(calls, 0);
  // Ten times the ray: 3.75 per sub-interval at the peak, so the bound cannot
  // decide and the peaks split the sub-intervals beside it as before.
  const double long_m = 10 * kFogLength_m;
  const auto long_peaks = piecesOf(long_m, 0.0, layer(long_m), kNoExtinctionBound);
  calls = 0;
  const auto long_bounded = piecesOf(long_m, 0.0, layer(long_m), 1e-4);
  EXPECT_GT(long_peaks.size(), static_cast<size_t>(kSegments));
  EXPECT_EQ(long_bounded, long_peaks);
  EXPECT_GT(calls, 0);
}

TEST(RayQuadrature, TheMediaBoundHoldsAtEveryAltitude) {
  // Earth-like coefficients, a Rayleigh profile that exceeds 1 near the
  // ground (clamped), an aerosol layer and a tent of absorption peaking at
  // 25 km; then the same with an absorption that outweighs the rest there,
  // so that a bound leaving out any constituent fails.
  for (const float absorption_per_m : {1.88e-6f, 1e-4f}) {
    AtmosphereParameters a;
    a.rayleigh_scattering = Spectrum(5.8e-6f, 13.5e-6f, 33.1e-6f, 0.0f);
    a.mie_extinction = Spectrum(4.4e-6f, 4.4e-6f, 4.4e-6f, 0.0f);
    a.absorption_extinction = Spectrum(0.65e-6f, absorption_per_m, 0.085e-6f, 0.0f);
    a.rayleigh_density = {{0.0, 1.5, -1.0 / 8000.0, 0.0, 0.0}};
    a.mie_density = {{0.0, 1.0, -1.0 / 1200.0, 0.0, 0.0}};
    a.absorption_density = {{25000.0, 0.0, 0.0, 1.0 / 15000.0, -2.0 / 3.0}, {0.0, 0.0, 0.0, -1.0 / 15000.0, 8.0 / 3.0}};
    const AtmosphereMedia media(a);
    const double bound = media.largestExtinctionBound();
    double largest = 0.0;
    for (double h = 0.0; h <= 100e3; h += 10.0) {
      ASSERT_LE(media.largestExtinction(h), bound) << h << " m, absorption " << absorption_per_m;
      largest = std::max(largest, media.largestExtinction(h));
    }
    // The bound assumes every density at 1 at once; here they peak apart,
    // so it is above the largest by what the others add where one peaks:
    // 0.2 % in the first atmosphere, 14 % in the second.
    EXPECT_GT(largest, 0.8 * bound) << absorption_per_m;
  }
}

TEST(RayQuadrature, NonFiniteExtinctionDoesNotLoop) {
  int nodes = 0;
  forEachOpticallyThinNode(
      0.0, 1000.0, kSegments, 0.0, [](double) { return INFINITY; }, [&](double, double) { ++nodes; });
  EXPECT_EQ(nodes, kGaussNodes * kSegments);
}

}  // namespace
}  // namespace skybake
