// The kernel files of the shell and the ray (data_formats/kernel/,
// runtime/kernel/) compiled as C++ in float, as the shaders evaluate them,
// against the same text in double, as the CPU runtime and the bake do: the
// tie between the two that holds on every machine, GPU or not. Inputs are
// float values, so that the difference is the float arithmetic's alone.
// kernel_tables_precision_test.cpp does the same for the tables' kernels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "data_formats/parameterization/ray_sphere.h"
#include "runtime/physics/atmosphere_ray.h"
#include "runtime/physics/density_profile.h"
#include "runtime/physics/multiple_scattering_phase.h"
#include "runtime/physics/phase_functions.h"
#include "runtime/physics/sun_disk.h"
#include "tests/data_formats/kernel_in_float.h"
#include "tests/data_formats/kernel_precision_support.h"

namespace skybake {
namespace {

namespace f = kernel_in_float;
using namespace kernel_precision;

// Radii from the ground to the top and zenith cosines from -1 to 1, on
// grids that include the ends and rays within a few texels of the horizon.
template <typename Visit>
void forEachRay(const Shell& s, Visit visit) {
  constexpr int kRadii = 41, kCosines = 401;
  for (int i = 0; i < kRadii; ++i) {
    const float r = s.bottom_m + (s.top_m - s.bottom_m) * static_cast<float>(i) / (kRadii - 1);
    for (int j = 0; j < kCosines; ++j) {
      const float mu = -1.0f + 2.0f * static_cast<float>(j) / (kCosines - 1);
      visit(r, mu);
    }
    // Around the horizon, where a distance changes fastest with mu.
    const float horizon = static_cast<float>(tangentZenithCosine(r, s.bottom_m));
    for (int k = -20; k <= 20; ++k) visit(r, std::clamp(horizon + 1e-4f * static_cast<float>(k), -1.0f, 1.0f));
  }
}

// Whether the ray's discriminant with the sphere is under a quarter of
// (r mu)^2: near tangency, where distanceTolerance's square-root term
// governs.
bool nearTangent(double r, double mu, double radius) {
  const double rmu_squared = r * mu * r * mu;
  return rmu_squared + (radius - r) * (radius + r) < 0.25 * rmu_squared;
}

TEST(KernelPrecision, ShellDistancesInFloatStayWithinFloatRoundingOfDouble) {
  for (const Shell& s : kShells) {
    forEachRay(s, [&](float r, float mu) {
      SCOPED_TRACE(testing::Message() << "r = " << r << " m, mu = " << mu);
      const double rd = r, mud = mu;
      const double to_top = distanceToOuterSphere(rd, mud, s.top_m);
      EXPECT_NEAR(f::skybakeDistanceToOuterSphere(r, mu, s.top_m), to_top, distanceTolerance(rd, mud, s.top_m));
      // Away from tangency the forms cancel nothing, so even a short
      // distance (a camera just below the top looking up) is good to a few
      // float roundoffs of itself, not of the radius.
      if (!nearTangent(rd, mud, s.top_m)) {
        EXPECT_NEAR(f::skybakeDistanceToOuterSphere(r, mu, s.top_m), to_top, 8.0 * kFloatEpsilon * to_top);
      }
      const double ground_discriminant = rd * rd * (mud * mud - 1.0) + double(s.bottom_m) * s.bottom_m;
      const bool hits_ground = rayIntersectsSphere(rd, mud, s.bottom_m);
      // Where the two disagree on hitting the ground, the ray is tangent
      // to it within float rounding of the discriminant.
      if (f::skybakeRayIntersectsSphere(r, mu, s.bottom_m) != hits_ground) {
        EXPECT_LE(std::abs(ground_discriminant), 8.0 * kFloatEpsilon * rd * rd);
      } else if (hits_ground) {
        const double to_ground = distanceToInnerSphere(rd, mud, s.bottom_m);
        const float to_ground_in_float = f::skybakeDistanceToInnerSphere(r, mu, s.bottom_m);
        EXPECT_NEAR(to_ground_in_float, to_ground, distanceTolerance(rd, mud, s.bottom_m));
        if (!nearTangent(rd, mud, s.bottom_m)) {
          EXPECT_NEAR(to_ground_in_float, to_ground, 8.0 * kFloatEpsilon * to_ground);
        }
      }
      // The horizon's cosine: sqrt((r - R)(r + R)) / r, each factor exact
      // or a roundoff; the root halves the relative error.
      EXPECT_NEAR(f::skybakeTangentZenithCosine(r, s.bottom_m), tangentZenithCosine(rd, s.bottom_m),
                  4.0 * kFloatEpsilon);
      // Along the ray, at a tenth and at all of its length to the top: the
      // radius is a root of a sum of radius-squared terms, good to a few
      // roundoffs of r + d.
      for (double fraction : {0.1, 1.0}) {
        const float d = static_cast<float>(fraction * to_top);
        const double r_d = radiusAlongRay(rd, mud, d);
        EXPECT_NEAR(f::skybakeRadiusAlongRay(r, mu, d), r_d, 8.0 * kFloatEpsilon * (rd + d));
        // The cosine there: (r mu + d) / r_d, clamped.
        EXPECT_NEAR(f::skybakeCosineAlongRay(r, mu, d, static_cast<float>(r_d)), cosineAlongRay(rd, mud, d, r_d),
                    8.0 * kFloatEpsilon * (rd + d) / r_d);
      }
    });
  }
}

// Entering the atmosphere from cameras on the ground, in it and in space
// (to geostationary distance), along directions from the zenith to the
// nadir. Away from tangency (to the top, where the ray enters, and to the
// sphere it ends on) every step is well conditioned: the start's float
// position errs by a roundoff of |start|, the entry point by a few of
// them, and the remaining length by a few roundoffs of itself plus the
// entry's error over a cosine of at least 1/2. Near tangency the ray may
// miss in one precision and graze in the other, which
// ShellDistancesInFloatStayWithinFloatRoundingOfDouble bounds.
TEST(KernelPrecision, EnteringTheAtmosphereInFloatStaysWithinFloatRoundingOfDouble) {
  const Shell earth = kShells[0];
  int entered = 0;
  for (float altitude_m : {0.0f, 2000.0f, 30e3f, 100e3f, 1000e3f, 35786e3f}) {
    const glm::vec3 start(0.0f, 0.0f, earth.bottom_m + altitude_m);
    for (int j = 0; j <= 400; ++j) {
      const float mu = -1.0f + 2.0f * static_cast<float>(j) / 400.0f;
      const glm::vec3 dir(std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu);
      const f::SkybakeRay in_float = f::skybakeEnterAtmosphere(earth.bottom_m, earth.top_m, start, dir);
      const AtmosphereRay in_double =
          atmosphereRay(earth.bottom_m, earth.top_m, glm::dvec3(start), glm::dvec3(dir), 0.0);
      const double r = start.z;
      if (nearTangent(r, mu, earth.top_m) || nearTangent(r, mu, earth.bottom_m)) continue;
      SCOPED_TRACE(testing::Message() << "altitude " << altitude_m << " m, mu = " << mu);
      ASSERT_EQ(in_float.inside, in_double.inside);
      if (!in_double.inside) continue;
      ++entered;
      EXPECT_EQ(in_float.ends_on_ground, in_double.ends_on_ground);
      const double scale = r + in_double.moved + in_double.length;
      EXPECT_NEAR(in_float.moved_m, in_double.moved, 8.0 * kFloatEpsilon * scale);
      EXPECT_NEAR(in_float.r, in_double.r, 8.0 * kFloatEpsilon * r);
      EXPECT_NEAR(in_float.length_m, in_double.length, 32.0 * kFloatEpsilon * scale);
    }
  }
  // 1391 of the 2406 rays enter away from tangency; the rest miss (most of
  // the sky seen from geostationary distance) or graze.
  EXPECT_GT(entered, 1300);
}

// The phase functions over every scattering cosine, for Rayleigh and for
// Cornette-Shanks from isotropic to a strong forward peak. The base
// 1 + g^2 - 2 g nu of Cornette-Shanks is a difference that cancels toward
// (1 - g)^2 at nu = 1: its float error is a few roundoffs of its terms,
// 1 + g^2 + 2 |g nu|, relative to it, and the power 1.5 multiplies that by
// 1.5; the rest is a few roundoffs.
TEST(KernelPrecision, PhaseFunctionsInFloatStayWithinFloatRoundingOfDouble) {
  constexpr int kCosines = 2001;
  for (int j = 0; j < kCosines; ++j) {
    const float nu = -1.0f + 2.0f * static_cast<float>(j) / (kCosines - 1);
    EXPECT_NEAR(f::skybakeRayleighPhase(nu), rayleighPhase(nu), 4.0 * kFloatEpsilon * rayleighPhase(nu));
    for (float g : {0.0f, 0.3f, -0.5f, 0.76f, 0.9f}) {
      const CornetteShanksPhase phase(g);
      const float normalisation = f::skybakeCornetteShanksNormalisation(g);
      EXPECT_NEAR(normalisation, phase.normalisation(), 8.0 * kFloatEpsilon * phase.normalisation());
      const double base = 1.0 + double(g) * g - 2.0 * double(g) * nu;
      const double tolerance =
          (1.5 * 8.0 * kFloatEpsilon * (1.0 + double(g) * g + 2.0 * std::abs(double(g) * nu)) / base +
           8.0 * kFloatEpsilon) *
          phase(nu);
      EXPECT_NEAR(f::skybakeCornetteShanksPhase(g, normalisation, nu), phase(nu), tolerance) << g << " " << nu;
      EXPECT_NEAR(f::skybakeCornetteShanksShape(g, nu), phase.shape(nu), tolerance / phase.normalisation());
    }
  }
}

// The multiple-scattering shape's Mie share and its blend of the broad part
// with the peak, from inputs rounded to float. The share: the two inputs'
// roundings move it by at most 2 roundoffs, the sum and the quotient by one
// each. The blend: the inputs' and the broad constant's roundings and those
// of the difference, product and sum, six in all, each within a roundoff of
// a magnitude that broad + w (|peak| + broad) bounds.
TEST(KernelPrecision, MultipleScatteringShapeInFloatStaysWithinFloatRoundingOfDouble) {
  for (double rayleigh : {0.0, 1e-12, 5.8e-6, 1.3e-3, 2.0}) {
    for (double mie : {0.0, 1e-12, 4.0e-6, 2.1e-2, 3.0}) {
      const double share = kernel::skybakeMieShare(rayleigh, mie);
      EXPECT_NEAR(f::skybakeMieShare(static_cast<float>(rayleigh), static_cast<float>(mie)), share,
                  4.0 * kFloatEpsilon * share)
          << rayleigh << " " << mie;
    }
  }
  EXPECT_EQ(f::skybakeMieShare(0.0f, 0.0f), 0.0f);  // nothing scatters: 0, not NaN
  const double broad = SKYBAKE_BROAD_PHASE;
  for (double w : {0.0, 0.02, 0.5, 1.0}) {
    for (double peak : {0.0, 0.05, broad, 0.5, 30.0}) {
      const double shape = kernel::skybakeMultipleShapeWithPeak(w, peak);
      EXPECT_NEAR(f::skybakeMultipleShapeWithPeak(static_cast<float>(w), static_cast<float>(peak)), shape,
                  6.0 * kFloatEpsilon * (broad + w * (std::abs(peak) + broad)))
          << w << " " << peak;
    }
  }
}

// The sun disk's visible fraction across the horizon, for the Sun's half
// size at Earth and a point sun. The smooth ramp's slope is at most 1.5 per
// disk diameter, so a float roundoff of height + half_size moves it by
// 1.5 roundoffs of that sum over the diameter.
TEST(KernelPrecision, SunDiskInFloatStaysWithinFloatRoundingOfDouble) {
  for (float half_size : {0.0f, 0.004675f, 0.05f}) {
    for (int i = -100; i <= 100; ++i) {
      const float height = 0.0001f * static_cast<float>(i);
      const double ramp_error =
          half_size > 0.0f ? 1.5 * 4.0 * kFloatEpsilon * (std::abs(height) + half_size) / (2.0 * half_size) : 0.0;
      EXPECT_NEAR(f::skybakeSunDiskVisibleFraction(height, half_size), sunDiskVisibleFraction(height, half_size),
                  ramp_error + 4.0 * kFloatEpsilon)
          << height << " " << half_size;
    }
  }
  EXPECT_NEAR(f::skybakeSunDiskHalfSizeAtHorizon(6360e3f, 6420e3f, 0.004675f),
              sunDiskHalfSizeAtHorizon(6360e3, 6420e3, 0.004675f), 4.0 * kFloatEpsilon * 0.004675);
}

// Density layers as the built-in Earth has them (Rayleigh's and Mie's
// exponentials, the ozone's two linear halves) from the ground to 100 km.
// exp(scale h) errs by a roundoff of its argument scale h, times the
// result, and the sum by a few roundoffs of its largest term; the clamp
// only removes error.
TEST(KernelPrecision, DensityLayerInFloatStaysWithinFloatRoundingOfDouble) {
  struct Layer {
    float exp_term, exp_scale_per_m, linear_term_per_m, constant_term;
  };
  constexpr Layer kLayers[] = {{1.0f, -1.0f / 8000.0f, 0.0f, 0.0f},
                               {1.0f, -1.0f / 1200.0f, 0.0f, 0.0f},
                               {0.0f, 0.0f, 1.0f / 15000.0f, -2.0f / 3.0f},
                               {0.0f, 0.0f, -1.0f / 15000.0f, 8.0f / 3.0f}};
  for (const Layer& l : kLayers) {
    for (int i = 0; i <= 1000; ++i) {
      const float h = 100.0f * static_cast<float>(i);
      const double exp_part = l.exp_term * std::exp(double(l.exp_scale_per_m) * h);
      const double largest =
          std::max({exp_part, std::abs(double(l.linear_term_per_m) * h), std::abs(double(l.constant_term))});
      const double tolerance = 2.0 * kFloatEpsilon * (1.0 + std::abs(double(l.exp_scale_per_m) * h)) * exp_part +
                               4.0 * kFloatEpsilon * largest;
      EXPECT_NEAR(
          f::skybakeLayerDensity(l.exp_term, l.exp_scale_per_m, l.linear_term_per_m, l.constant_term, h),
          layerDensity(DensityLayer{0.0, l.exp_term, l.exp_scale_per_m, l.linear_term_per_m, l.constant_term}, h),
          tolerance)
          << h;
    }
  }
}

// The kernel's cancellation-free forms in double against the textbook
// forms in double: the same numbers to double rounding of the
// radius-squared terms, so the CPU's results moved by rounding only.
TEST(KernelPrecision, ShellDistancesInDoubleAreTheTextbookForms) {
  constexpr double kDoubleEpsilon = std::numeric_limits<double>::epsilon() / 2.0;
  for (const Shell& s : kShells) {
    forEachRay(s, [&](float r, float mu) {
      const double rd = r, mud = mu, top = s.top_m, bottom = s.bottom_m;
      const double top_discriminant = rd * rd * (mud * mud - 1.0) + top * top;
      const double textbook_to_top = std::max(-rd * mud + std::sqrt(std::max(top_discriminant, 0.0)), 0.0);
      // The textbook form's own error: roundoffs of the r^2-sized terms
      // through the root, as distanceTolerance reasons in float.
      const double terms = rd * std::abs(mud) + std::sqrt(std::max(top_discriminant, 0.0));
      const double discriminant_error = 8.0 * kDoubleEpsilon * rd * rd;
      const double tolerance =
          8.0 * kDoubleEpsilon * terms + discriminant_error / (terms + std::sqrt(discriminant_error));
      EXPECT_NEAR(distanceToOuterSphere(rd, mud, top), textbook_to_top, tolerance) << r << " " << mu;
      EXPECT_NEAR(tangentZenithCosine(rd, bottom), -std::sqrt(std::max(1.0 - (bottom / rd) * (bottom / rd), 0.0)),
                  1e-7)  // the textbook form's 1 - x^2 loses half the digits near the ground: sqrt(eps)
          << r;
    });
  }
}

}  // namespace
}  // namespace skybake
