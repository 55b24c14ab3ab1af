// The bake's cubic in the logarithm across the sun axis
// (baker/numerics/log_cubic.h).
#include <gtest/gtest.h>

#include <cmath>

#include "baker/numerics/log_cubic.h"

namespace skybake {
namespace {

// The blend from four texels' values at evenly spaced nodes 0..3, at
// position 1 + t (interior), or from the first three as an axis's end.
Spectrum blendOf(const float (&v)[4], float t, bool before_is_end = false) {
  Spectrum value[4], logarithm[4];
  for (int i = 0; i < 4; ++i) {
    value[i] = Spectrum(v[i]);
    logarithm[i] = Spectrum(std::log(v[i]));
  }
  if (before_is_end)
    return blendLogCubic({value[0], value[1], logarithm[0], logarithm[0], logarithm[1], logarithm[2], true, false}, t);
  return blendLogCubic({value[1], value[2], logarithm[0], logarithm[1], logarithm[2], logarithm[3], false, false}, t);
}

// Catmull-Rom reproduces quadratics exactly, so a quantity whose logarithm
// is quadratic in the texel index (an exponential whose decay rate changes
// with depression) comes out exact up to float rounding: the logarithms
// (magnitude < 10) carry 1e-6 relative error, which exp turns into 1e-5 of
// the value at most.
TEST(LogCubic, ExactForALogQuadratic) {
  auto f = [](float x) { return std::exp(-1.7f * x + 0.15f * x * x); };
  const float v[4] = {f(0.0f), f(1.0f), f(2.0f), f(3.0f)};
  for (float t : {0.0f, 0.2f, 0.5f, 0.8f, 1.0f}) {
    EXPECT_NEAR(blendOf(v, t)[0], f(1.0f + t), 1e-5f * f(1.0f + t)) << "t " << t;
  }
}

// At an axis's end the logarithm is extended linearly: a pure exponential
// stays exact there. A linear blend would be 9 % high at t = 0.5 (values 1
// and e^-1.7 apart).
TEST(LogCubic, ExactForAnExponentialAtTheAxisEnd) {
  auto f = [](float x) { return std::exp(-1.7f * x); };
  const float v[4] = {f(0.0f), f(1.0f), f(2.0f), f(3.0f)};
  for (float t : {0.25f, 0.5f, 0.75f}) {
    EXPECT_NEAR(blendOf(v, t, true)[0], f(t), 1e-5f * f(t)) << "t " << t;
  }
  EXPECT_GT((v[0] + v[1]) * 0.5f, 1.05f * blendOf(v, 0.5f, true)[0]);
}

// A texel without a logarithm (zero) blends linearly, finite.
TEST(LogCubic, ZeroNeighbourBlendsLinearly) {
  const float v[4] = {0.0f, 2.0f, 1.0f, 0.5f};
  EXPECT_FLOAT_EQ(blendOf(v, 0.5f)[0], 1.5f);
}

// Data that do not fall monotonically, and a denormal beside normal
// numbers: the result stays finite and within the interval's two texels.
TEST(LogCubic, StaysWithinTheInterval) {
  const float cases[][4] = {{1e-3f, 1.0f, 1.0f, 1e-3f}, {1.0f, 1e-40f, 1.0f, 1e-40f}, {3e38f, 1.0f, 2.0f, 1e-44f}};
  for (const auto& v : cases) {
    for (float t : {0.1f, 0.5f, 0.9f}) {
      const float b = blendOf(v, t)[0];
      EXPECT_TRUE(std::isfinite(b));
      EXPECT_GE(b, std::min(v[1], v[2]) * (1.0f - 1e-5f)) << v[0] << " " << v[1] << " " << v[2] << " t " << t;
      EXPECT_LE(b, std::max(v[1], v[2]) * (1.0f + 1e-5f)) << v[0] << " " << v[1] << " " << v[2] << " t " << t;
    }
  }
}

}  // namespace
}  // namespace skybake
