// What the kernel precision tests share: float's roundoff, the shells they
// sweep and the float error of a distance to a sphere.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace skybake::kernel_precision {

// Float's unit roundoff.
constexpr double kFloatEpsilon = std::numeric_limits<float>::epsilon() / 2.0;

// Earth's shell, and a thin and a thick one (ratios top / bottom of
// 1.0005 and 2), where the cancellations the kernel avoids are worst and
// least.
struct Shell {
  float bottom_m, top_m;
};
constexpr Shell kShells[] = {{6360e3f, 6420e3f}, {6360e3f, 6363e3f}, {1000e3f, 2000e3f}};

// A distance of the shell in float against double. Its inputs are exact;
// the float result errs by a few roundoffs of the terms it combines, r |mu|
// and sqrt(discriminant), and by the error of the discriminant itself
// ((r mu)^2 +- (R - r)(R + r), a few roundoffs of its two terms), which the
// square root turns into up to its own square root where the discriminant
// is near 0: a ray near tangent to the sphere, whose distance there changes
// by as much for a change of mu by a float roundoff. The factors 8 allow
// for the rounding of each product and sum on the way.
inline double distanceTolerance(double r, double mu, double radius) {
  const double rmu_squared = r * mu * r * mu, q = (radius - r) * (radius + r);
  const double discriminant = rmu_squared + q;
  const double discriminant_error = 8.0 * kFloatEpsilon * (rmu_squared + std::abs(q));
  const double root = std::sqrt(std::max(discriminant, 0.0));
  const double root_error =
      discriminant_error > 0.0 ? discriminant_error / (root + std::sqrt(discriminant_error)) : 0.0;
  return 8.0 * kFloatEpsilon * (r * std::abs(mu) + root) + root_error;
}

}  // namespace skybake::kernel_precision
