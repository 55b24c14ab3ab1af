// The tables' kernel files (where a lookup lies in the tables, the
// interpolation weights, the night continuation, the planet's shadow and
// the moon's occlusion) compiled as C++ in float, as the shaders evaluate
// them, against the same text in double, as the CPU runtime and the bake
// do: the tie between the two that holds on every machine, GPU or not.
// Inputs are float values, so that the difference is the float
// arithmetic's alone; each tolerance is a few float roundoffs (epsilon) of
// the terms a result is made of, carried through its condition.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "data_formats/config/config.h"
#include "data_formats/parameterization/texture_mapping.h"
#include "runtime/physics/moon_occluder.h"
#include "runtime/physics/night_sky.h"
#include "runtime/physics/planet_shadow.h"
#include "runtime/tables/table_sampler.h"
#include "tests/data_formats/kernel_in_float.h"
#include "tests/data_formats/kernel_precision_support.h"

namespace skybake {
namespace {

namespace f = kernel_in_float;

using namespace kernel_precision;
// Float's unit roundoff, under a short name.
constexpr double kEps = kFloatEpsilon;
// The float error of a distance to a sphere.
constexpr auto& distanceError = distanceTolerance;

// The error of x = (dist - lo) / (hi - lo) from the distance's and the
// ends' errors (each end a few roundoffs of itself).
double fractionError(double dist_error, double lo, double hi) {
  return (dist_error + 8.0 * kEps * (std::abs(lo) + std::abs(hi))) / (hi - lo) + 4.0 * kEps;
}

// The 4D tables' mu coordinate over rays from the ground to the top, both
// halves and the sky-only layout. u = 0.5 -+ x / 2 (less a half texel), so
// its error is half x's; x is the distance's position in its range, whose
// error fractionError carries (large only where the range shrinks to a
// point, at r = bottom for the ground half, where both sides give 0).
TEST(KernelTablesPrecision, ScatteringMuCoordinateInFloatStaysWithinFloatRoundingOfDouble) {
  constexpr int kSizeMu = 128;
  for (const Shell& s : kShells) {
    const double bottom = s.bottom_m, top = s.top_m;
    const float H = static_cast<float>(kernel::skybakeDistanceToHorizon(top, bottom));
    for (int i = 1; i <= 40; ++i) {
      const float r = s.bottom_m + (s.top_m - s.bottom_m) * static_cast<float>(i) / 40.0f;
      const float rho = f::skybakeDistanceToHorizon(r, s.bottom_m);
      for (int j = 0; j <= 400; ++j) {
        const float mu = -1.0f + 2.0f * static_cast<float>(j) / 400.0f;
        const bool ground = rayIntersectsSphere(r, mu, bottom);
        if (ground != f::skybakeRayIntersectsSphere(r, mu, s.bottom_m)) continue;  // tangent: the other test's
        for (bool ground_views : {true, false}) {
          const double in_double =
              kernel::skybakeScatteringCoordMu(r, mu, bottom, top, rho, H, kSizeMu, ground_views, ground);
          const float in_float =
              f::skybakeScatteringCoordMu(r, mu, s.bottom_m, s.top_m, rho, H, kSizeMu, ground_views, ground);
          double tolerance;
          if (ground_views && ground) {
            tolerance = 0.5 * fractionError(distanceError(r, mu, bottom), r - bottom, rho);
          } else {
            tolerance = (ground_views ? 0.5 : 1.0) * fractionError(distanceError(r, mu, top), top - r, rho + H);
          }
          EXPECT_NEAR(in_float, in_double, tolerance) << r << " " << mu << " " << ground_views;
        }
      }
    }
  }
}

// The unit sun coordinate over every sun, for the built-in Earth's axis
// (split at the horizon, down to its lowest sun) and Bruneton's alone.
// Above the horizon it is a smooth function of a = (distance - d_min) /
// span with slope at most 1 + 1/A, rescaled by the day's share; below it
// the depth s of t = mu_s / mu_s_min, with slope at most 1 / c.
TEST(KernelTablesPrecision, SunCoordinateInFloatStaysWithinFloatRoundingOfDouble) {
  const BakeConfig config = builtinEarthConfig();
  for (SunAxisMapping axis : {SunAxisMapping::SplitAtHorizon, SunAxisMapping::DistanceToTop}) {
    AtmosphereDomain domain = AtmosphereDomain::fromParameters(config.atmosphere);
    domain.sun_axis = axis;
    const MuSUnitCoordMap m = MuSUnitCoordMap::of(domain);
    f::SkybakeSunCoordMap mf{};
    mf.bottom_radius_m = static_cast<float>(m.bottom_radius_m);
    mf.top_radius_m = static_cast<float>(m.top_radius_m);
    mf.d_min = static_cast<float>(m.d_min);
    mf.inverse_d_span = static_cast<float>(m.inverse_d_span);
    mf.inverse_A = static_cast<float>(m.inverse_A);
    mf.defined = static_cast<float>(m.defined);
    mf.below_share = static_cast<float>(m.below_share);
    mf.day_coord_at_horizon = static_cast<float>(m.day_coord_at_horizon);
    mf.inverse_mu_s_min = static_cast<float>(m.inverse_mu_s_min);
    mf.horizon_spacing = static_cast<float>(m.horizon_spacing);
    const double day_scale = m.below_share > 0.0 ? (1.0 - m.below_share) / (1.0 - m.day_coord_at_horizon) : 1.0;
    for (int j = 0; j <= 2000; ++j) {
      const float mu_s = static_cast<float>(std::max(domain.mu_s_min, -1.0 + 2.0 * j / 2000.0));
      // The map's constants rounded to float move the result as much as
      // the arithmetic does: both are a few roundoffs of each term.
      double tolerance;
      if (m.below_share > 0.0 && mu_s < 0.0) {
        tolerance = m.below_share / m.horizon_spacing * 2.0 * kEps + 2.0 * kEps;
      } else {
        const double dist = distanceToOuterSphere(m.bottom_radius_m, mu_s, m.top_radius_m);
        // distanceError's factors 8 are a generous bound; the distance to
        // the top from the ground is well conditioned for every sun.
        const double a_error =
            (distanceError(m.bottom_radius_m, mu_s, m.top_radius_m) / 4.0 + 2.0 * kEps * (dist + m.d_min)) *
            m.inverse_d_span;
        tolerance = day_scale * (1.0 + m.inverse_A) * (a_error + 2.0 * kEps) + 2.0 * kEps;
      }
      EXPECT_NEAR(f::skybakeSunUnitCoord(mf, mu_s), m(mu_s), tolerance) << mu_s;
    }
  }
}

// The axis weights: the position i0 + w1 on the axis is u size - 0.5 in
// either precision, to a roundoff of size; the neighbours are the same
// except where that position is within a roundoff of a texel.
TEST(KernelTablesPrecision, AxisWeightsInFloatStayWithinFloatRoundingOfDouble) {
  for (int size : {2, 8, 32, 128}) {
    for (int j = -10; j <= 1010; ++j) {
      const float u = static_cast<float>(j) / 1000.0f;
      const kernel::SkybakeAxisLerp in_double = kernel::skybakeAxisLerp(u, size);
      const f::SkybakeAxisLerp in_float = f::skybakeAxisLerp(u, size);
      EXPECT_NEAR(in_float.i0 + in_float.w1, in_double.i0 + in_double.w1, 4.0 * kEps * size) << u << " " << size;
      EXPECT_LE(std::abs(in_float.i0 - in_double.i0), 1);
      const kernel::SkybakeAxisLerp nu_double = kernel::skybakeAxisLerpNu(u, size);
      const f::SkybakeAxisLerp nu_float = f::skybakeAxisLerpNu(u, size);
      EXPECT_NEAR(nu_float.i0 + nu_float.w1, nu_double.i0 + nu_double.w1, 4.0 * kEps * size) << u << " " << size;
    }
  }
}

// The blends of two texels from 1e-30 to 1e30 apart. The geometric blend
// is exp of a sum of logarithms: the roundoffs of log a and log b, of
// magnitude up to 70, become relative errors of the result of that many
// roundoffs; the share of it is smooth in the ratio (slope at most 3 over
// the ratio's span of 0.5), whose float error is a few roundoffs.
TEST(KernelTablesPrecision, BlendsInFloatStayWithinFloatRoundingOfDouble) {
  const float values[] = {0.0f, 1e-30f, 1e-5f, 0.3f, 1.0f, 1.2f, 1.49f, 1.6f, 1.9f, 2.5f, 40.0f, 1e30f};
  for (float a : values) {
    for (float b : values) {
      for (float w : {0.0f, 0.1f, 0.5f, 0.77f, 1.0f}) {
        const double logs = std::abs(std::log(std::max(a, 1e-38f))) + std::abs(std::log(std::max(b, 1e-38f)));
        const double scale = std::max(a, b);
        const double tolerance = (kEps * (1.0 + logs) + 6.0 / 0.5 * 2.0 * kEps) * scale;
        EXPECT_NEAR(f::skybakeBlendGeometricWhereSteep(a, b, w), kernel::skybakeBlendGeometricWhereSteep(a, b, w),
                    tolerance)
            << a << " " << b << " " << w;
        for (float share : {0.0f, 0.4f, 1.0f}) {
          EXPECT_NEAR(f::skybakeBlendGeometricWherePositive(a, b, w, share),
                      kernel::skybakeBlendGeometricWherePositive(a, b, w, share), tolerance)
              << a << " " << b << " " << w << " " << share;
        }
      }
    }
  }
}

// The night scale's base 1 - tan(d / 2) k below the built-in Earth's
// lowest sun, k = 1 / tan(span / 2): tan(d / 2) = sin d / (1 + cos d), the
// sine and cosine of d a few roundoffs each, the quotient's error
// magnified by 1 / (1 + cos d) (below 2 for d up to 90 deg).
TEST(KernelTablesPrecision, NightScaleInFloatStaysWithinFloatRoundingOfDouble) {
  const BakeConfig config = builtinEarthConfig();
  const AtmosphereDomain domain = AtmosphereDomain::fromParameters(config.atmosphere);
  const NightContinuation night = nightContinuationOf(domain, Texture2D{});
  ASSERT_GT(night.inverse_tan_half_span, 0.0);
  const float edge = static_cast<float>(night.edge_mu_s), edge_sin = static_cast<float>(night.edge_sin);
  const float k = static_cast<float>(night.inverse_tan_half_span);
  for (int j = 0; j <= 1000; ++j) {
    const float mu_s = -1.0f + (edge + 1.0f) * static_cast<float>(j) / 1000.0f;
    const double in_double = kernel::skybakeNightScaleBase(mu_s, edge, edge_sin, k);
    const double sin_s = std::sqrt(std::max(1.0 - double(mu_s) * mu_s, 0.0));
    const double cos_d = double(mu_s) * edge + sin_s * edge_sin;
    // sin_s is the square root of 1 - mu_s^2, whose roundoff (of 1) it
    // carries as roundoff / (2 sin_s): large near mu_s = -1, where sin_s is
    // small (0 exactly at -1, in either precision).
    const double sin_error = 2.0 * kEps + (sin_s > 0.0 ? std::min(kEps / sin_s, std::sqrt(kEps)) : 0.0);
    EXPECT_NEAR(f::skybakeNightScaleBase(mu_s, edge, edge_sin, k), in_double,
                2.0 * k * (sin_error + 2.0 * kEps) / ((1.0 + cos_d) * (1.0 + cos_d)) + 2.0 * kEps)
        << mu_s;
  }
}

// Crossings of the planet's shadow, for rays from the ground to the top of
// Earth's atmosphere toward every side of a sun from above to below the
// horizon. The crossings are the roots t of qa t^2 + qb t + qc with qa = 1 -
// nu^2, qb = 2 r (mu - mu_s nu), qc = r^2 (1 - mu_s^2) - R^2, taken without
// cancellation: each errs by a few roundoffs of t and of the larger root,
// plus the discriminant's error (roundoffs of its r^2-sized terms) through
// its square root, as for the spheres. Where the counts differ the ray
// grazes the cylinder (the discriminant is within its error of 0) or a
// root lies within its tolerance of the segment's ends.
TEST(KernelTablesPrecision, PlanetShadowInFloatStaysWithinFloatRoundingOfDouble) {
  const Shell earth = kShells[0];
  const double bottom = earth.bottom_m;
  int crossings = 0;
  for (float altitude_m : {0.0f, 1000.0f, 10e3f, 40e3f}) {
    const float r = earth.bottom_m + altitude_m;
    for (float mu : {-0.5f, -0.05f, -0.01f, 0.0f, 0.02f, 0.1f, 0.5f, 1.0f}) {
      for (float mu_s : {0.3f, 0.0f, -0.05f, -0.1f, -0.2f, -0.3f}) {
        for (int k = 0; k <= 16; ++k) {
          const double spread = std::sqrt((1.0 - double(mu) * mu) * (1.0 - double(mu_s) * mu_s));
          const float nu = static_cast<float>(double(mu) * mu_s + spread * std::cos(kPi * k / 16.0));
          const float length = static_cast<float>(distanceToOuterSphere(r, mu, earth.top_m)) * 3.0f;
          const ShadowCrossings d = planetShadowCrossings(r, mu, mu_s, nu, bottom, length);
          const f::SkybakeShadowCrossings fl = f::skybakePlanetShadowCrossings(r, mu, mu_s, nu, earth.bottom_m, length);
          const double qa = 1.0 - double(nu) * nu, qb = 2.0 * r * (mu - double(mu_s) * nu);
          const double qc = double(r) * r * (1.0 - double(mu_s) * mu_s) - bottom * bottom;
          const double discriminant = qb * qb - 4.0 * qa * qc;
          const double discriminant_error = 16.0 * kEps * (qb * qb + 4.0 * qa * (std::abs(qc) + double(r) * r));
          const double root = std::sqrt(std::max(discriminant, 0.0));
          const double larger_root = (std::abs(qb) + root) / (2.0 * qa);
          const double root_error = discriminant_error / (root + std::sqrt(discriminant_error)) / (2.0 * qa);
          auto tolerance = [&](double t) { return 16.0 * kEps * (t + larger_root) + root_error; };
          SCOPED_TRACE(testing::Message() << "r " << r << " mu " << mu << " mu_s " << mu_s << " nu " << nu);
          if (fl.count != d.count) {
            bool near_boundary = std::abs(discriminant) <= discriminant_error;
            for (int i = 0; i < d.count; ++i) {
              near_boundary |= d.distance[i] < tolerance(0.0) || length - d.distance[i] < tolerance(length);
            }
            EXPECT_TRUE(near_boundary);
            continue;
          }
          for (int i = 0; i < d.count; ++i) {
            ++crossings;
            EXPECT_NEAR(i == 0 ? fl.distance_m.x : fl.distance_m.y, d.distance[i], tolerance(d.distance[i]));
          }
        }
      }
    }
  }
  EXPECT_GT(crossings, 500);
}

// The fraction of the sun a moon leaves, seen from points on the ground
// around a total eclipse's centre line. The moon's centre (3.8e8 m away)
// is a float roundoff of its distance off, a few 1e-8 rad as seen from the
// ground, and the angles a few roundoffs more; the covered fraction moves
// at most 2 / (pi sun radius) per radian of either.
TEST(KernelTablesPrecision, MoonOcclusionInFloatStaysWithinFloatRoundingOfDouble) {
  const double sun_radius_rad = 0.004675;
  const glm::dvec3 sun_dir = glm::normalize(glm::dvec3(0.2, 0.1, 1.0));
  const Moon moon = Moon::seenFrom(glm::dvec3(0.0, 0.0, 6360e3), sun_dir, 0.0048);
  const glm::vec3 centre_f(moon.centre_m);
  const double angle_error = kEps * (1.0 + glm::length(moon.centre_m) / kMeanLunarDistance_m);
  const double tolerance = angle_error * 2.0 / (kPi * sun_radius_rad) + 2.0 * kEps;
  int partial = 0;
  for (int i = -60; i <= 60; ++i) {
    const glm::vec3 point(static_cast<float>(i) * 2000.0f, 0.0f, 6360e3f);
    const double in_double = kernel::skybakeMoonVisibleSunFraction(
        glm::dvec3(centre_f), static_cast<float>(moon.radius_m), glm::dvec3(point), glm::dvec3(glm::vec3(sun_dir)),
        static_cast<float>(sun_radius_rad));
    const float in_float = f::skybakeMoonVisibleSunFraction(centre_f, static_cast<float>(moon.radius_m), point,
                                                            glm::vec3(sun_dir), static_cast<float>(sun_radius_rad));
    EXPECT_NEAR(in_float, in_double, tolerance) << i;
    partial += in_double > 0.0 && in_double < 1.0;
  }
  // The sweep crosses the umbra's edge into the penumbra.
  EXPECT_GT(partial, 10);
}

}  // namespace
}  // namespace skybake
