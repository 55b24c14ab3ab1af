// The test that lets the twilight integrals skip stretches of a ray in the
// planet's shadow (runtime/physics/sunless_segment.h).
#include "runtime/physics/sunless_segment.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "data_formats/parameterization/ray_sphere.h"
#include "runtime/physics/sun_disk.h"

namespace skybake {
namespace {

constexpr double kBottom_m = 6360e3;
constexpr double kTop_m = 6420e3;
constexpr double kSunAngularRadius_rad = 0.00467;

// The sun's visible fraction at distance t along the ray as the
// integrators compute it at a node (TableSampler::SunDiskAtR).
double visibleAt(double r, double mu, double mu_s, double nu, double t) {
  const double r_t = std::clamp(radiusAlongRay(r, mu, t), kBottom_m, kTop_m);
  const double mu_s_t = clampCosine((r * mu_s + t * nu) / r_t);
  return sunDiskVisibleFraction(mu_s_t - tangentZenithCosine(r_t, kBottom_m),
                                sunDiskHalfSizeAtHorizon(kBottom_m, r_t, kSunAngularRadius_rad));
}

TEST(SunlessSegment, NoPointOfASunlessStretchSeesTheSun) {
  // Cameras from the ground to the top, suns from 80 to 120 deg, views and
  // azimuths everywhere; stretches of every length along each ray. A
  // stretch called sunless must read exactly 0 at 400 points along it (the
  // nodes of any rule on it lie among such points' neighbours, and the
  // margin keeps them far from the ramp: a point 1e-9 R^2 inside the region
  // is 5e-10 below the ramp in cosine).
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int sunless = 0, partly_lit = 0, tested = 0;
  for (int ray = 0; ray < 3000; ++ray) {
    const double r = kBottom_m + (kTop_m - kBottom_m) * unit(random);
    const double mu = -1.0 + 2.0 * unit(random);
    const double sun_zenith = (80.0 + 40.0 * unit(random)) * 3.14159265358979 / 180.0;
    const double mu_s = std::cos(sun_zenith);
    const double azimuth = 2.0 * 3.14159265358979 * unit(random);
    const double nu = mu * mu_s + std::sqrt(1.0 - mu * mu) * std::sin(sun_zenith) * std::cos(azimuth);
    const bool ground = rayIntersectsSphere(r, mu, kBottom_m);
    const double length = distanceToAtmosphereEnd(r, mu, kBottom_m, kTop_m, ground);
    const SunlessSegmentTest test(r, mu, mu_s, nu, kBottom_m, kSunAngularRadius_rad);
    for (int s = 0; s < 4; ++s) {
      double a = length * unit(random), b = length * unit(random);
      if (a > b) std::swap(a, b);
      ++tested;
      bool lit = false;
      for (int k = 0; k <= 400; ++k) lit = lit || visibleAt(r, mu, mu_s, nu, a + (b - a) * k / 400.0) > 0.0;
      if (test.sunless(a, b)) {
        ++sunless;
        ASSERT_FALSE(lit) << "r " << r << " mu " << mu << " mu_s " << mu_s << " nu " << nu << " [" << a << ", " << b
                          << "]";
      } else if (lit) {
        ++partly_lit;
      }
    }
  }
  // The test decides for most dark stretches (else it saves nothing): in
  // these twilights about half of all stretches are dark.
  EXPECT_GT(sunless, tested / 4);
  EXPECT_GT(partly_lit, tested / 10);
}

TEST(SunlessSegment, StretchesAcrossThePenumbraAreNotSunless) {
  // From the ground, the sun 92 deg from the zenith, looking up toward it:
  // the ray leaves the shadow through the penumbra. A stretch from the
  // camera to just past the first point that sees the disk's upper limb is
  // not sunless; one that stops short of the penumbra is.
  const double r = kBottom_m, mu = 0.5;
  const double sun_zenith = 92.0 * 3.14159265358979 / 180.0;
  const double mu_s = std::cos(sun_zenith);
  const double nu = mu * mu_s + std::sqrt(1.0 - mu * mu) * std::sin(sun_zenith);
  const double length = distanceToAtmosphereEnd(r, mu, kBottom_m, kTop_m, false);
  const SunlessSegmentTest test(r, mu, mu_s, nu, kBottom_m, kSunAngularRadius_rad);
  // The first lit point along the ray, to 1 m.
  double first_lit = length;
  for (double t = 0.0; t < length; t += 1.0) {
    if (visibleAt(r, mu, mu_s, nu, t) > 0.0) {
      first_lit = t;
      break;
    }
  }
  ASSERT_LT(first_lit, length);
  EXPECT_TRUE(test.sunless(0.0, 0.99 * first_lit));
  EXPECT_FALSE(test.sunless(0.0, first_lit + 1.0));
}

}  // namespace
}  // namespace skybake
