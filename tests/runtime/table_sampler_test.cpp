// Interpolation in the baked tables: the blends stay finite and exact where
// they should, whatever the magnitudes.
#include <gtest/gtest.h>

#include <cmath>

#include "data_formats/config/config.h"
#include "runtime/tables/table_sampler.h"

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
  // Neighbours within SKYBAKE_GEOMETRIC_BLEND_RATIO blend linearly.
  const Spectrum near = blendGeometricWhereSteep(Spectrum(1.0f), Spectrum(1.2f), 0.5f);
  EXPECT_FLOAT_EQ(near[0], 1.1f);
}

// No jump where the neighbours' ratio reaches SKYBAKE_GEOMETRIC_BLEND_RATIO
// (or SKYBAKE_FULLY_GEOMETRIC_BLEND_RATIO): as the ratio of two nu slices changes with the
// sun, a switch there made the sky step. Midway between 1 and b the linear
// and geometric blends differ by (1 + b) / 2 - sqrt(b): 0.0253 at b = 1.5
// (1.0 % of 1.25), so a switch jumps by that. With the smooth move from one to
// the other, steps of 1e-4 in b change the blend by about their own size
// times its slope (< 0.5) plus the share's change times that difference
// (slope of the share at most 3 per unit ratio): below 1e-4 * (0.5 + 3 *
// 0.06) = 7e-5, bounded here by 1e-4; a switch fails by 250x.
TEST(TableSampler, GeometricBlendMovesSmoothlyFromLinearAsNeighboursDrawApart) {
  float previous = blendGeometricWhereSteep(Spectrum(1.0f), Spectrum(1.4f), 0.5f)[0];
  EXPECT_FLOAT_EQ(previous, 1.2f);  // within the linear range
  for (int i = 1; i <= 8000; ++i) {
    const float b = 1.4f + 1e-4f * static_cast<float>(i);
    const float blended = blendGeometricWhereSteep(Spectrum(1.0f), Spectrum(b), 0.5f)[0];
    ASSERT_LT(std::abs(blended - previous), 1e-4f) << "b " << b;
    ASSERT_LE(blended, 0.5f * (1.0f + b) * (1.0f + 1e-6f)) << "between the geometric and linear blends, b " << b;
    ASSERT_GE(blended, std::sqrt(b) * (1.0f - 1e-6f)) << "between the geometric and linear blends, b " << b;
    previous = blended;
  }
  EXPECT_NEAR(previous, std::sqrt(2.2f), 1e-6f);  // wholly geometric from SKYBAKE_FULLY_GEOMETRIC_BLEND_RATIO on
}

// The scattering density falls steeply with the sun below the horizon (tenfold
// between sun texels in deep twilight); a lookup there blends its sun
// texels geometrically, as radiance lookups do, and linearly by day. A linear
// blend read 5.5 midway between 1 and 10 instead of 3.16, and rays to a point
// in twilight, integrated over the density, were 3.1 / 3.8 / 3.6 % RMS off the
// reference instead of 2.6 / 2.2 / 3.3 % (default Earth bake, standard set).
TEST(TableSampler, DensityBlendsSunTexelsGeometricallyBelowTheHorizonOnly) {
  const BakeConfig config = builtinEarthConfig();
  TextureSizes sizes = config.sizes;
  sizes.scattering_r = 4;
  sizes.scattering_mu = 8;
  sizes.scattering_mu_s = 16;
  sizes.scattering_nu = 4;
  const AtmosphereDomain domain = AtmosphereDomain::fromParameters(config.atmosphere);
  const TableSampler sampler(domain, sizes);
  Texture4D density(4, 8, 16, 4);
  for (int i_r = 0; i_r < 4; ++i_r)
    for (int i_mu = 0; i_mu < 8; ++i_mu)
      for (int i_mu_s = 0; i_mu_s < 16; ++i_mu_s)
        for (int i_nu = 0; i_nu < 4; ++i_nu) density.at(i_r, i_mu, i_mu_s, i_nu) = Spectrum(std::pow(10.0f, i_mu_s));
  const double r = domain.bottom_radius_m + 5000.0;
  for (int i = 0; i + 1 < 16; ++i) {
    const double mu_s = muSFromUnitCoord(domain, (i + 0.5) / 15.0);  // midway between sun texels i and i + 1
    const float low = std::pow(10.0f, i);
    // Float rounding of the blend and the table's coordinate (1e-6 of the
    // texel spacing moves the result by 2e-6 of it): 1e-4 relative.
    const float expected = mu_s < 0.0 ? std::sqrt(low * 10.0f * low) : 5.5f * low;
    EXPECT_NEAR(sampler.multipleDensity(density, r, 0.3, mu_s, 0.2)[0] / expected, 1.0f, 1e-4f) << "mu_s " << mu_s;
  }
}

}  // namespace
}  // namespace skybake

namespace skybake {
namespace {

// The batch lookups' slice sampling is sample4D with its r and mu_s axes
// reduced to one texel: the same numbers exactly, for both blends, since a
// blend of a texel with itself at weight 0 returns it unchanged.
TEST(TableSampler, SliceSamplingEqualsSample4DOnASingleTexelAxis) {
  Texture4D slice(1, 6, 1, 4);
  float x = 0.37f;
  for (Spectrum& v : slice.texels) {
    v = Spectrum(x, 3.0f * x, 0.01f * x, 0.0f);
    x = x * 1.91f + 0.13f;
    if (x > 50.0f) x = 0.011f;
  }
  const AxisLerp single{0, 0, 0.0f};
  for (double u_mu : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    for (double u_nu : {0.0, 0.2, 0.61, 1.0}) {
      const AxisLerp mu = axisLerpFromTextureCoord(u_mu, slice.mu_size);
      const AxisLerp nu = axisLerpNu(u_nu, slice.nu_size);
      EXPECT_EQ(sampleMuNuSlice<Blend::Linear>(slice, mu, nu), sample4D<Blend::Linear>(slice, single, mu, single, nu));
      EXPECT_EQ(sampleMuNuSlice<Blend::GeometricWhereSteep>(slice, mu, nu),
                sample4D<Blend::GeometricWhereSteep>(slice, single, mu, single, nu));
    }
  }
}

}  // namespace
}  // namespace skybake
