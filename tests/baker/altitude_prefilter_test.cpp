// The 4D tables prefiltered across r (baker/bake/altitude_prefilter.h): what a
// linear blend of the stored texels reads between them.
#include "baker/bake/altitude_prefilter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace skybake {
namespace {

constexpr int kRTexels = 16;

// A table of 2 (mu) x 1 x 1 texels per r holding f(r index) in channel 0,
// 2 f in channel 1 and 0 in the others.
Texture4D tableOf(const std::function<double(double)>& f) {
  Texture4D t(kRTexels, 2, 1, 1);
  for (int r = 0; r < kRTexels; ++r) {
    for (int mu = 0; mu < 2; ++mu) t.at(r, mu, 0, 0) = Spectrum(f(r), 2.0 * f(r), 0.0f, 0.0f);
  }
  return t;
}

// The linear blend's mean relative error over every interval between texels
// (r index i + w, w in (0, 1), 64 points each), for i in [first, end).
double meanBlendError(const Texture4D& t, const std::function<double(double)>& f, int first, int end) {
  double sum = 0.0;
  int n = 0;
  for (int i = first; i < end; ++i) {
    for (int k = 0; k < 64; ++k) {
      const double w = (k + 0.5) / 64.0;
      const double blend = (1.0 - w) * t.at(i, 1, 0, 0)[0] + w * t.at(i + 1, 1, 0, 0)[0];
      sum += (blend - f(i + w)) / f(i + w);
      ++n;
    }
  }
  return sum / n;
}

TEST(AltitudePrefilter, TheBlendOverAnExponentialIsUnbiased) {
  // The sky seen from a camera falls off with its altitude about as
  // exp(-h / 8 km); the default r texels are 2.7 km apart 30 km up, a
  // ratio of 1.4 between neighbours.
  const auto f = [](double x) { return std::exp(-0.34 * x); };
  Texture4D t = tableOf(f);
  const double before = meanBlendError(t, f, 0, kRTexels - 1);
  prefilterAcrossAltitude(t);
  // The intervals beside the ends, which keep their values, are half corrected.
  const double after = meanBlendError(t, f, 1, kRTexels - 2);
  // Unfiltered, the blend reads high by about (q + 1/q - 2) / 12 = 0.96 %
  // on average (q = e^0.34). Prefiltered, the mean of the blend's absolute
  // error vanishes to second order in the spacing; its mean relative error
  // here works out at -1.5e-4 (the relative weighting and fourth-order
  // terms), 65 times less: 3e-4 allowed, an eighth of what a prefilter a
  // quarter too weak or too strong would leave.
  EXPECT_GT(before, 0.009);
  EXPECT_LT(std::abs(after), 3e-4) << "before " << before;
}

TEST(AltitudePrefilter, KeepsTheEndsAndStraightLines) {
  const auto line = [](double x) { return 3.0 + 0.5 * x; };
  Texture4D t = tableOf(line);
  const Texture4D original = t;
  prefilterAcrossAltitude(t);
  // A second difference of a line is 0: nothing to correct, to float
  // rounding of values near 10.
  for (size_t i = 0; i < t.texels.size(); ++i) {
    for (int c = 0; c < kMaxChannels; ++c) EXPECT_NEAR(t.texels[i][c], original.texels[i][c], 1e-5);
  }
  Texture4D curved = tableOf([](double x) { return std::exp(0.3 * x); });
  const Texture4D curved_original = curved;
  prefilterAcrossAltitude(curved);
  // The ground and the top, where cameras sit exactly, keep their values.
  for (int mu = 0; mu < 2; ++mu) {
    EXPECT_EQ(curved.at(0, mu, 0, 0), curved_original.at(0, mu, 0, 0));
    EXPECT_EQ(curved.at(kRTexels - 1, mu, 0, 0), curved_original.at(kRTexels - 1, mu, 0, 0));
  }
  EXPECT_LT(curved.at(5, 0, 0, 0)[0], curved_original.at(5, 0, 0, 0)[0]);
}

TEST(AltitudePrefilter, AnEdgeOfDarknessStaysPositiveAndNear) {
  // Light that starts between two texels (the planet's shadow): 0 below
  // texel 8, 1 from it on. The formula would move texel 8 by -1/12 of its
  // neighbours' jump and texel 7 from 0 to -1/12; the limit keeps each
  // within kMaxAltitudePrefilterShare of its own value.
  Texture4D t = tableOf([](double x) { return x >= 8.0 ? 1.0 : 0.0; });
  prefilterAcrossAltitude(t);
  EXPECT_EQ(t.at(7, 0, 0, 0)[0], 0.0f);
  EXPECT_GE(t.at(8, 0, 0, 0)[0], 1.0f - kMaxAltitudePrefilterShare);
  EXPECT_LE(t.at(8, 0, 0, 0)[0], 1.0f + kMaxAltitudePrefilterShare);
  for (const Spectrum& texel : t.texels) {
    for (int c = 0; c < kMaxChannels; ++c) EXPECT_GE(texel[c], 0.0f);
  }
}

}  // namespace
}  // namespace skybake
