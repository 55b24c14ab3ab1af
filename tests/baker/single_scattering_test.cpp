// Single scattering against the closed form for a flat, exponentially
// stratified, non-absorbing atmosphere of one constituent (camera on the
// ground, sun cosine s, view cosine v, optical thickness b = beta H):
//   L / (E P(nu)) = s (exp(-b/s) - exp(-b/v)) / (s - v),  (b/v) exp(-b/v) at s = v.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/stages/optical_depth_table.h"
#include "baker/stages/single_scattering_tables.h"
#include "runtime/physics/planet_shadow.h"
#include "runtime/physics/single_scattering_ray.h"
#include "test_configs.h"

namespace skybake {
namespace {

double flatSingleScattering(double b, double s, double v) {
  if (std::abs(s - v) < 1e-9) return (b / v) * std::exp(-b / v);
  return s * (std::exp(-b / s) - std::exp(-b / v)) / (s - v);
}

// 1 %: the bound. The bake's own error budget is far below it: the
// ray rule is accurate to ~1e-4, the transmittance table to ~1e-4 in optical
// depth; the emulated flat atmosphere differs from a truly flat one through
// curvature, which at v = 0.2 lifts the ray by d^2 / 2R = 0.02 scale heights
// where most light is scattered, a few 1e-3 of the result.
constexpr double kTolerance = 0.01;

void checkAgainstClosedForm(bool mie, double scale_height_m) {
  const BakeConfig config = test::flatSingleConstituent(mie, scale_height_m);
  const AtmosphereParameters& a = config.atmosphere;
  SilentProgress silent;
  const TableSampler sampler(AtmosphereDomain::fromParameters(a), config.sizes);
  const StageContext ctx{a, sampler, silent};
  const Texture2D optical_depth = computeOpticalDepthTable(ctx);
  const double b = (mie ? a.mie_extinction[0] : a.rayleigh_scattering[0]) * scale_height_m;
  for (double s : {0.2, 0.35, 0.6, 1.0}) {
    for (double v : {0.2, 0.35, 0.6, 1.0}) {
      // Any nu the geometry allows; the closed form holds for all (phase aside).
      const double nu = s * v;
      const SingleScattering single = computeSingleScattering(ctx, optical_depth, a.bottom_radius_m, v, s, nu, false);
      const double computed = mie ? single.mie[0] : single.rayleigh[0];
      const double expected = a.sun_irradiance[0] * flatSingleScattering(b, s, v);
      EXPECT_NEAR(computed / expected, 1.0, kTolerance) << (mie ? "Mie" : "Rayleigh") << " s=" << s << " v=" << v;
    }
  }
}

TEST(SingleScattering, RayleighMatchesFlatAtmosphereClosedForm) { checkAgainstClosedForm(false, 8000.0); }

// The thin Mie layer (H = 1.2 km) is the hard case: a ray rule whose steps are
// not small against the scale height overestimates it.
TEST(SingleScattering, MieMatchesFlatAtmosphereClosedForm) { checkAgainstClosedForm(true, 1200.0); }

// The same closed form against the tables the bake stores: every ground
// texel (r = bottom exactly at texel 0) of a sky ray whose view and sun are
// both at least 0.2 above the horizon, where the emulated flat atmosphere's
// curvature stays below the tolerance (see kTolerance).
void checkTablesAgainstClosedForm(bool mie, double scale_height_m) {
  BakeConfig config = test::flatSingleConstituent(mie, scale_height_m);
  // Texels concentrate near the horizon, where this check does not hold:
  // enough of them to leave a few dozen above 0.2 (28 for the thin Mie layer).
  config.sizes.scattering_r = 2;
  config.sizes.scattering_mu = 512;
  config.sizes.scattering_mu_s = 32;
  config.sizes.scattering_nu = 2;
  const AtmosphereParameters& a = config.atmosphere;
  SilentProgress silent;
  const TableSampler sampler(AtmosphereDomain::fromParameters(a), config.sizes);
  const StageContext ctx{a, sampler, silent};
  const Texture2D optical_depth = computeOpticalDepthTable(ctx);
  Texture4D rayleigh, mie_table;
  computeSingleScatteringTables(ctx, optical_depth, rayleigh, mie_table);
  const double b = (mie ? a.mie_extinction[0] : a.rayleigh_scattering[0]) * scale_height_m;
  const ScatteringSizes& s = sampler.scatteringSizes();
  int checked = 0;
  for (int i_mu = s.mu / 2; i_mu < s.mu; ++i_mu) {
    for (int i_mu_s = 0; i_mu_s < s.mu_s; ++i_mu_s) {
      const ScatteringTexelConfig c = scatteringTexelConfig(sampler.domain(), s, 0, i_mu, i_mu_s, 0);
      if (c.mu < 0.2 || c.mu_s < 0.2) continue;
      const double stored = (mie ? mie_table : rayleigh).at(0, i_mu, i_mu_s, 0)[0];
      EXPECT_NEAR(stored / (a.sun_irradiance[0] * flatSingleScattering(b, c.mu_s, c.mu)), 1.0, kTolerance)
          << (mie ? "Mie" : "Rayleigh") << " mu_s=" << c.mu_s << " mu=" << c.mu;
      ++checked;
    }
  }
  EXPECT_GE(checked, 20);
}

TEST(SingleScattering, RayleighTablesMatchFlatAtmosphereClosedForm) { checkTablesAgainstClosedForm(false, 8000.0); }
TEST(SingleScattering, MieTablesMatchFlatAtmosphereClosedForm) { checkTablesAgainstClosedForm(true, 1200.0); }

// The bake fills its tables with a batched form of the runtime's ray
// integral (integrateSingleScattering, through computeSingleScattering): the
// nodes of a view ray are shared by every sun the planet's shadow leaves
// alone, the exponentials are vectorized and summed in float. Texel by
// texel the two agree to float rounding: each texel sums at most a few
// hundred terms of relative rounding ~1e-7, so 1e-5 of the texel's value
// (plus 1e-6 of the table's largest, for texels near 0 in the shadow) is
// far above rounding and far below any difference of rule or geometry (a
// rule with one sub-interval fewer moves texels by ~1e-4).
void expectTablesMatchTheRayIntegral(const AtmosphereDomain& domain, const TextureSizes& sizes) {
  const BakeConfig config = test::smallEarth(1);
  const AtmosphereParameters& a = config.atmosphere;
  SilentProgress silent;
  const TableSampler sampler(domain, sizes);
  const StageContext ctx{a, sampler, silent};
  const Texture2D optical_depth = computeOpticalDepthTable(ctx);
  Texture4D rayleigh, mie;
  computeSingleScatteringTables(ctx, optical_depth, rayleigh, mie);
  const ScatteringSizes& s = sampler.scatteringSizes();
  Spectrum largest(0.0f);
  for (const Spectrum& v : rayleigh.texels) largest = glm::max(largest, v);
  for (int i_r = 0; i_r < s.r; ++i_r)
    for (int i_mu = 0; i_mu < s.mu; ++i_mu)
      for (int i_mu_s = 0; i_mu_s < s.mu_s; ++i_mu_s)
        for (int i_nu = 0; i_nu < s.nu; ++i_nu) {
          const ScatteringTexelConfig c = scatteringTexelConfig(domain, s, i_r, i_mu, i_mu_s, i_nu);
          const SingleScattering ray =
              computeSingleScattering(ctx, optical_depth, c.r, c.mu, c.mu_s, c.nu, c.ray_intersects_ground);
          for (int ch = 0; ch < a.channelCount(); ++ch) {
            const float tolerance_rayleigh = 1e-5f * ray.rayleigh[ch] + 1e-6f * largest[ch];
            ASSERT_NEAR(rayleigh.at(i_r, i_mu, i_mu_s, i_nu)[ch], ray.rayleigh[ch], tolerance_rayleigh)
                << "texel " << i_r << " " << i_mu << " " << i_mu_s << " " << i_nu;
            ASSERT_NEAR(mie.at(i_r, i_mu, i_mu_s, i_nu)[ch], ray.mie[ch], 1e-5f * ray.mie[ch] + 1e-6f * largest[ch])
                << "texel " << i_r << " " << i_mu << " " << i_mu_s << " " << i_nu;
          }
        }
}

TEST(SingleScattering, TablesEqualTheRayIntegralAtEveryTexel) {
  const BakeConfig config = test::smallEarth(1);
  expectTablesMatchTheRayIntegral(AtmosphereDomain::fromParameters(config.atmosphere), config.sizes);
}

// A narrowed domain of twilight suns and sky views only: most rays cross the
// planet's shadow, where the bake integrates each sun's ray piece by piece.
TEST(SingleScattering, TablesEqualTheRayIntegralInTwilightAndOnNarrowedAxes) {
  const BakeConfig config = test::smallEarth(1);
  AtmosphereDomain d = AtmosphereDomain::fromParameters(config.atmosphere);
  d.scattering_rho_max_m = d.distanceToHorizon(d.bottom_radius_m + 15000.0);
  d.scattering_mu_s_coord_min = 0.0;
  d.scattering_mu_s_coord_max = muSUnitCoord(d, std::cos(radiansFromDegrees(80.0)));
  d.scattering_ground_views = false;
  expectTablesMatchTheRayIntegral(d, config.sizes);
}

// One view ray's integral under many suns (SingleScatteringAlongRay, the
// bake's twilight sky irradiance) is integrateSingleScattering's exactly:
// the same nodes summed in the same order, whether the planet's shadow cuts
// the ray or not. Rays up, along and below the horizon from the ground and
// from altitude; suns from the day to deep twilight; every azimuth.
TEST(SingleScattering, OneRayUnderManySunsIsTheRayIntegral) {
  const BakeConfig config = test::smallEarth(1);
  const AtmosphereParameters& a = config.atmosphere;
  SilentProgress silent;
  const TableSampler sampler(AtmosphereDomain::fromParameters(a), config.sizes);
  const StageContext ctx{a, sampler, silent};
  const Texture2D optical_depth = computeOpticalDepthTable(ctx);
  int cut = 0, checked = 0;
  for (double altitude_m : {0.0, 3000.0, 40000.0}) {
    const double r = a.bottom_radius_m + altitude_m;
    for (double mu : {1.0, 0.5, 0.1, 0.0, -0.05, -0.3}) {
      const bool ground = rayIntersectsSphere(r, mu, a.bottom_radius_m);
      const double length = distanceToAtmosphereEnd(r, mu, a.bottom_radius_m, a.top_radius_m, ground);
      const SingleScatteringAlongRay along(sampler, optical_depth, a, r, mu, ground, 0.0, length, 4);
      for (double sun_zenith_deg : {30.0, 89.0, 91.0, 95.0, 102.0}) {
        const double mu_s = std::cos(radiansFromDegrees(sun_zenith_deg));
        for (int k = 0; k < 12; ++k) {
          const double phi = 2.0 * kPi * k / 12.0;
          const double nu =
              clampCosine(safeSqrt(1.0 - mu * mu) * safeSqrt(1.0 - mu_s * mu_s) * std::cos(phi) + mu * mu_s);
          const SingleScattering expected =
              integrateSingleScattering(sampler, optical_depth, a, {r, mu, mu_s, nu, ground}, 0.0, length, 4);
          const SingleScattering got = along.under(mu_s, nu);
          cut += planetShadowCrossings(r, mu, mu_s, nu, a.bottom_radius_m, length).count > 0;
          ++checked;
          for (int c = 0; c < a.channelCount(); ++c) {
            ASSERT_EQ(got.rayleigh[c], expected.rayleigh[c])
                << altitude_m << " " << mu << " " << sun_zenith_deg << " " << k;
            ASSERT_EQ(got.mie[c], expected.mie[c]) << altitude_m << " " << mu << " " << sun_zenith_deg << " " << k;
          }
        }
      }
    }
  }
  // Both paths of the class were taken: rays the shadow cuts and rays it does not.
  EXPECT_GT(cut, checked / 10);
  EXPECT_LT(cut, checked);
}

}  // namespace
}  // namespace skybake
