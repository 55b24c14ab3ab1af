// The parameterization round-trips: the configuration at a texel's centre maps
// back to that texel's centre, on both sides of the horizon split and at the
// domain ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "data_formats/angles.h"
#include "data_formats/config/config.h"
#include "data_formats/parameterization/texture_mapping.h"

namespace skybake {
namespace {

// Texture coordinates are computed in double from distances up to ~1e7 m;
// round-off stays near 1e-12. 1e-9 of the unit range is 1e-7 of a texel at
// 128 texels: any real mapping error is far larger.
constexpr double kCoordTolerance = 1e-9;
// Except at the ground half's horizon texel (i_mu = 0): its ray is tangent
// to the ground, where the distance is the square root of a discriminant
// that is 0 in exact arithmetic. The roundoff of its terms, a few epsilon
// times rho^2, moves the distance by sqrt(few epsilon) = about 3e-8 of rho
// and the coordinate by half that fraction of the half axis: 1e-7 of the
// unit range is still 1e-5 of a texel.
constexpr double kTangentCoordTolerance = 1e-7;

class TextureMapping : public ::testing::Test {
 protected:
  BakeConfig config = builtinEarthConfig();
  AtmosphereDomain domain = AtmosphereDomain::fromParameters(config.atmosphere);
  ScatteringSizes sizes = ScatteringSizes::fromTextureSizes(config.sizes);
};

double centre(int i, int n) { return (i + 0.5) / n; }

TEST_F(TextureMapping, ScatteringTexelCentresRoundTrip) {
  for (int i_r = 0; i_r < sizes.r; ++i_r) {
    for (int i_mu = 0; i_mu < sizes.mu; ++i_mu) {
      for (int i_mu_s = 0; i_mu_s < sizes.mu_s; ++i_mu_s) {
        const ScatteringTexelConfig c = scatteringTexelConfig(domain, sizes, i_r, i_mu, i_mu_s, 0);
        ASSERT_EQ(c.ray_intersects_ground, i_mu < sizes.mu / 2);
        const ScatteringCoord u =
            scatteringCoordFromRMuMuSNu(domain, sizes, c.r, c.mu, c.mu_s, c.nu, c.ray_intersects_ground);
        EXPECT_NEAR(u.u_r, centre(i_r, sizes.r), kCoordTolerance);
        EXPECT_NEAR(u.u_mu_s, centre(i_mu_s, sizes.mu_s), kCoordTolerance) << i_mu_s;
        // At r = bottom every ground ray is straight down (the range of
        // distances is empty); only the sky half round-trips there.
        if (i_r > 0 || !c.ray_intersects_ground) {
          EXPECT_NEAR(u.u_mu, centre(i_mu, sizes.mu), i_mu == 0 ? kTangentCoordTolerance : kCoordTolerance)
              << i_r << " " << i_mu;
        }
      }
    }
  }
}

TEST_F(TextureMapping, DomainEndsSitOnTexelCentres) {
  EXPECT_DOUBLE_EQ(rFromScatteringTexel(domain, sizes, 0), domain.bottom_radius_m);
  EXPECT_NEAR(rFromScatteringTexel(domain, sizes, sizes.r - 1), domain.top_radius_m, 1e-6);
  // mu_s: the first texel is the lowest sun of the domain, the last the zenith.
  EXPECT_NEAR(muSFromScatteringTexel(domain, sizes, 0), domain.mu_s_min, 1e-9);
  EXPECT_NEAR(muSFromScatteringTexel(domain, sizes, sizes.mu_s - 1), 1.0, 1e-12);
  // mu: both halves start at the horizon on the outside and meet at the
  // vertical: ground rows run from the horizon (0) to straight down (mu/2 - 1),
  // sky rows from straight up (mu/2) to the horizon (mu - 1).
  const int r_mid = sizes.r / 2;
  const double r = rFromScatteringTexel(domain, sizes, r_mid);
  const double horizon_mu = -domain.distanceToHorizon(r) / r;
  EXPECT_NEAR(scatteringTexelConfig(domain, sizes, r_mid, 0, 0, 0).mu, horizon_mu, 1e-9);
  EXPECT_NEAR(scatteringTexelConfig(domain, sizes, r_mid, sizes.mu / 2 - 1, 0, 0).mu, -1.0, 1e-9);
  EXPECT_NEAR(scatteringTexelConfig(domain, sizes, r_mid, sizes.mu / 2, 0, 0).mu, 1.0, 1e-9);
  EXPECT_NEAR(scatteringTexelConfig(domain, sizes, r_mid, sizes.mu - 1, 0, 0).mu, horizon_mu, 1e-9);
  // nu: linear over [-1, 1], texels on both ends, then limited to what (mu,
  // mu_s) allow: looking straight up with the sun at the zenith, nu = 1.
  EXPECT_NEAR(scatteringTexelConfig(domain, sizes, r_mid, sizes.mu / 2, sizes.mu_s - 1, 0).nu, 1.0, 1e-9);
  const ScatteringTexelConfig low = scatteringTexelConfig(domain, sizes, r_mid, sizes.mu - 1, sizes.mu_s - 1, 0);
  EXPECT_NEAR(low.nu, clampNu(-1.0, low.mu, low.mu_s), 1e-12);
  EXPECT_NEAR(scatteringCoordFromRMuMuSNu(domain, sizes, r, 0.0, 0.0, -1.0, false).u_nu, 0.0, 1e-15);
  EXPECT_NEAR(scatteringCoordFromRMuMuSNu(domain, sizes, r, 0.0, 0.0, 1.0, false).u_nu, 1.0, 1e-15);
}

TEST_F(TextureMapping, HorizonSplitSeparatesGroundAndSkyRays) {
  // Just above and just below the horizon, the two rays land on opposite
  // sides of u_mu = 0.5 and never in the same texel.
  const double r = domain.bottom_radius_m + 1000.0;
  const double horizon_mu = -domain.distanceToHorizon(r) / r;
  // The distance to the ground grows like sqrt(mu - horizon) off the tangent;
  // 1e-9 in mu keeps it within 40 m of the tangent distance (0.03 % of rho).
  const ScatteringCoord sky = scatteringCoordFromRMuMuSNu(domain, sizes, r, horizon_mu + 1e-9, 0.5, 0.0, false);
  const ScatteringCoord ground = scatteringCoordFromRMuMuSNu(domain, sizes, r, horizon_mu - 1e-9, 0.5, 0.0, true);
  EXPECT_GT(sky.u_mu, 0.5);
  EXPECT_LT(ground.u_mu, 0.5);
  // ... and both sit at the outer ends of their halves, the horizon texels.
  EXPECT_NEAR(sky.u_mu, 1.0 - 0.5 / sizes.mu, 1e-3);
  EXPECT_NEAR(ground.u_mu, 0.5 / sizes.mu, 1e-3);
}

TEST_F(TextureMapping, TransmittanceAndIrradianceTexelCentresRoundTrip) {
  const TextureSizes& s = config.sizes;
  for (int i_r = 0; i_r < s.transmittance_r; ++i_r) {
    for (int i_mu = 0; i_mu < s.transmittance_mu; ++i_mu) {
      const RMu rm = transmittanceTexelConfig(domain, s.transmittance_mu, s.transmittance_r, i_mu, i_r);
      const TextureCoord2D uv = transmittanceCoordFromRMu(domain, s.transmittance_mu, s.transmittance_r, rm.r, rm.mu);
      EXPECT_NEAR(uv.u, centre(i_mu, s.transmittance_mu), kCoordTolerance);
      EXPECT_NEAR(uv.v, centre(i_r, s.transmittance_r), kCoordTolerance);
    }
  }
  // The irradiance table's rows and suns, as version 9 places them and as
  // earlier versions did.
  AtmosphereDomain linear_rows = domain;
  linear_rows.irradiance_rows = IrradianceRows::Linear;
  for (const AtmosphereDomain& d : {domain, linear_rows}) {
    for (int i_r = 0; i_r < s.irradiance_r; ++i_r) {
      for (int i_mu_s = 0; i_mu_s < s.irradiance_mu_s; ++i_mu_s) {
        const RMuS rm = irradianceTexelConfig(d, s.irradiance_mu_s, s.irradiance_r, i_mu_s, i_r);
        const TextureCoord2D uv = irradianceCoordFromRMuS(d, s.irradiance_mu_s, s.irradiance_r, rm.r, rm.mu_s);
        EXPECT_NEAR(uv.u, centre(i_mu_s, s.irradiance_mu_s), kCoordTolerance);
        EXPECT_NEAR(uv.v, centre(i_r, s.irradiance_r), kCoordTolerance);
      }
    }
  }
}

// Version 9's irradiance rows: cosine spaced (the Earth's 16 rows: the
// first 0.66 km up, the last but one 59.34 km), and each row's sun axis
// puts that row's own sunset on the texel of the horizon.
TEST_F(TextureMapping, IrradianceRowsAreCosineSpacedOnTheirOwnHorizon) {
  const TextureSizes& s = config.sizes;
  ASSERT_EQ(domain.irradiance_rows, IrradianceRows::CosineOverDepth);
  const double thickness_m = domain.top_radius_m - domain.bottom_radius_m;
  const int last = s.irradiance_r - 1;
  auto altitude = [&](int i_r) {
    return irradianceTexelConfig(domain, 1, s.irradiance_r, 0, i_r).r - domain.bottom_radius_m;
  };
  EXPECT_EQ(altitude(0), 0.0);
  EXPECT_NEAR(altitude(last), thickness_m, 1e-6);
  EXPECT_NEAR(altitude(1), thickness_m * (1.0 - std::cos(kPi / last)) / 2.0, 1e-6);
  EXPECT_NEAR(altitude(last - 1) / thickness_m, (1.0 + std::cos(kPi / last)) / 2.0, 1e-9);
  // Each row's own sunset sits where the ground's horizon does on the sun
  // axis; the axis's ends (the lowest sun, the zenith) stay.
  const double ground_horizon_u =
      irradianceCoordFromRMuS(domain, s.irradiance_mu_s, s.irradiance_r, domain.bottom_radius_m, 0.0).u;
  for (double altitude_m : {2000.0, 30000.0, 59000.0}) {
    const double r = domain.bottom_radius_m + altitude_m;
    const double own_horizon = -std::sqrt(1.0 - std::pow(domain.bottom_radius_m / r, 2.0));
    auto u = [&](double mu_s) { return irradianceCoordFromRMuS(domain, s.irradiance_mu_s, s.irradiance_r, r, mu_s).u; };
    EXPECT_NEAR(u(own_horizon), ground_horizon_u, 1e-12) << altitude_m;
    EXPECT_LT(u(0.0), 1.0) << altitude_m;
    EXPECT_GT(u(0.0), ground_horizon_u) << altitude_m;
    EXPECT_NEAR(u(1.0),
                irradianceCoordFromRMuS(domain, s.irradiance_mu_s, s.irradiance_r, domain.bottom_radius_m, 1.0).u,
                1e-12);
    EXPECT_NEAR(
        u(domain.mu_s_min),
        irradianceCoordFromRMuS(domain, s.irradiance_mu_s, s.irradiance_r, domain.bottom_radius_m, domain.mu_s_min).u,
        1e-12);
  }
}

}  // namespace
}  // namespace skybake
