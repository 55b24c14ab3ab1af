// The 4D tables prefiltered across mu_s below the horizon
// (baker/bake/sun_prefilter.h): what the twilight lookups' blend of the
// stored texels reads between them.
#include "baker/bake/sun_prefilter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "runtime/tables/table_sampler.h"

namespace skybake {
namespace {

// 12 texels below the horizon (sun cosines -0.12 .. -0.01), one on it and
// four above.
constexpr int kSunTexels = 17;
constexpr int kHorizonTexel = 12;

std::vector<double> texelMuS() {
  std::vector<double> mu_s(kSunTexels);
  for (int i = 0; i < kSunTexels; ++i) mu_s[i] = 0.01 * (i - kHorizonTexel);
  return mu_s;
}

// A table of 2 (r) x 1 x 1 texels per mu_s holding f(mu_s index) in
// channel 0, 0.5 f in channel 1 and 0 in the others.
Texture4D tableOf(const std::function<double(double)>& f) {
  Texture4D t(2, 1, kSunTexels, 1);
  for (int r = 0; r < 2; ++r) {
    for (int i = 0; i < kSunTexels; ++i) t.at(r, 0, i, 0) = Spectrum(f(i), 0.5 * f(i), 0.0f, 0.0f);
  }
  return t;
}

// The twilight lookups' blend's mean relative error over the intervals
// [first, end) between texels, 64 points each, channel `c`.
double meanBlendError(const Texture4D& t, const std::function<double(double)>& f, int first, int end, int c = 0) {
  double sum = 0.0;
  int n = 0;
  for (int i = first; i < end; ++i) {
    for (int k = 0; k < 64; ++k) {
      const double w = (k + 0.5) / 64.0;
      const double blend =
          blendAcross<Blend::GeometricWhereSteep>(t.at(1, 0, i, 0), t.at(1, 0, i + 1, 0), static_cast<float>(w))[c];
      const double truth = (c == 0 ? 1.0 : 0.5) * f(i + w);
      sum += (blend - truth) / truth;
      ++n;
    }
  }
  return sum / n;
}

TEST(SunPrefilter, TheGeometricBlendOverAConcaveLogarithmIsUnbiased) {
  // The twilight sky from the ground falls 2.2 to 2.7 times from one default
  // sun texel to the next between 92 and 97 deg: a logarithm whose slope
  // grows by about 0.1 per texel. Here ln f = -0.8 d - 0.05 d^2 at d
  // texels below the horizon (ratios 2.3 to 7 between neighbours, every
  // blend wholly geometric).
  const auto f = [](double x) {
    const double d = kHorizonTexel - x;
    return std::exp(-0.8 * d - 0.05 * d * d);
  };
  Texture4D t = tableOf(f);
  const double before = meanBlendError(t, f, 0, kHorizonTexel);
  prefilterAcrossSunBelowHorizon(t, texelMuS());
  // The interval beside the lowest texel, which keeps its value, is half
  // corrected; the one ending on the horizon texel too.
  const double after = meanBlendError(t, f, 1, kHorizonTexel - 1);
  const double after_half_blue = meanBlendError(t, f, 1, kHorizonTexel - 1, 1);
  // Unfiltered, the blend of a logarithm with second derivative -0.1 reads
  // low by 0.1 / 12 = 0.83 % on average; prefiltered its mean vanishes to
  // second order (what is left is the relative weighting and fourth-order
  // terms, about 1e-5 here): 1e-3 allowed, an eighth of what a prefilter
  // an eighth too weak or too strong would leave.
  EXPECT_LT(before, -0.008);
  EXPECT_LT(std::abs(after), 1e-3) << "before " << before;
  EXPECT_LT(std::abs(after_half_blue), 1e-3);
}

TEST(SunPrefilter, TheLinearBlendOfGentleNeighboursIsUnbiased) {
  // Neighbours within 1.2 of each other are blended linearly; an
  // exponential then reads high by (q + 1/q - 2) / 12 = 0.24 % (q = 1.19).
  const auto f = [](double x) { return std::exp(0.17 * x); };
  Texture4D t = tableOf(f);
  const double before = meanBlendError(t, f, 0, kHorizonTexel);
  prefilterAcrossSunBelowHorizon(t, texelMuS());
  const double after = meanBlendError(t, f, 1, kHorizonTexel - 1);
  // As AltitudePrefilter's: second order gone, 65 times less; a tenth of
  // the bias allowed.
  EXPECT_GT(before, 0.0023);
  EXPECT_LT(std::abs(after), 2.5e-4) << "before " << before;
}

TEST(SunPrefilter, KeepsTheDayTheHorizonAndTheLowestSun) {
  const auto f = [](double x) { return std::exp(0.5 * x + 0.04 * x * x); };
  Texture4D t = tableOf(f);
  const Texture4D original = t;
  prefilterAcrossSunBelowHorizon(t, texelMuS());
  for (int r = 0; r < 2; ++r) {
    // Day lookups blend the texels from the horizon up linearly, and the
    // lowest sun's texel is an end of the axis: all kept as baked.
    EXPECT_EQ(t.at(r, 0, 0, 0), original.at(r, 0, 0, 0));
    for (int i = kHorizonTexel; i < kSunTexels; ++i) EXPECT_EQ(t.at(r, 0, i, 0), original.at(r, 0, i, 0)) << i;
    // Below the horizon every texel is corrected (a convex logarithm: lowered).
    for (int i = 1; i < kHorizonTexel; ++i) EXPECT_LT(t.at(r, 0, i, 0)[0], original.at(r, 0, i, 0)[0]) << i;
  }
}

TEST(SunPrefilter, ACorrectionNeverTakesMoreThanItsShare) {
  // The edge of the night: a texel between a bright neighbour and a dark
  // one (zero), where the second difference is no curvature.
  Texture4D t = tableOf([](double x) { return x < 6.0 ? 0.0 : (x < 7.0 ? 1.0 : 40.0); });
  const Texture4D original = t;
  prefilterAcrossSunBelowHorizon(t, texelMuS());
  for (int i = 1; i < kHorizonTexel; ++i) {
    const float value = original.at(0, 0, i, 0)[0];
    EXPECT_LE(std::abs(t.at(0, 0, i, 0)[0] - value), kMaxSunPrefilterShare * value + 1e-7f) << i;
    EXPECT_GE(t.at(0, 0, i, 0)[0], 0.0f);
  }
}

}  // namespace
}  // namespace skybake
