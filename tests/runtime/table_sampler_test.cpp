// Interpolation in the baked tables: the blends stay finite and exact where
// they should, whatever the magnitudes.
#include <gtest/gtest.h>

#include <cmath>

#include "runtime/table_sampler.h"

namespace skybake {
namespace {

// Thick or dark atmospheres leave denormal texels next to normal ones; the
// ratio of the two overflows float, and a blend through it was infinite.
TEST(TableSampler, GeometricBlendIsFiniteAcrossDenormalNeighbours) {
  const Spectrum dark(1e-40f, 1e-44f, 1e-38f, 0.0f), bright(1.0f, 3e38f, 1e-30f, 1.0f);
  for (float w : {0.0f, 0.25f, 0.5f, 1.0f}) {
    const Spectrum b = blendGeometricWhereSteep(dark, bright, w);
    for (int c = 0; c < 4; ++c) {
      EXPECT_TRUE(std::isfinite(b[c])) << "channel " << c << " w " << w;
      EXPECT_GE(b[c], std::min(dark[c], bright[c]) * 0.999f) << "channel " << c << " w " << w;
      EXPECT_LE(b[c], std::max(dark[c], bright[c]) * 1.001f) << "channel " << c << " w " << w;
    }
  }
}

// Exact for exponential falloff (what it is for): midway between 1 and 100
// lies 10, within float rounding (1e-6).
TEST(TableSampler, GeometricBlendFollowsAnExponential) {
  EXPECT_NEAR(geometricBlend(1.0f, 100.0f, 0.5f), 10.0f, 1e-5f);
  const Spectrum b = blendGeometricWhereSteep(Spectrum(1.0f), Spectrum(100.0f), 0.5f);
  EXPECT_NEAR(b[0], 10.0f, 1e-5f);
  // Neighbours within kGeometricBlendRatio blend linearly.
  const Spectrum near = blendGeometricWhereSteep(Spectrum(1.0f), Spectrum(1.2f), 0.5f);
  EXPECT_FLOAT_EQ(near[0], 1.1f);
}

}  // namespace
}  // namespace skybake
