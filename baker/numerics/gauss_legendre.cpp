#include "baker/numerics/gauss_legendre.h"

#include "data_formats/angles.h"

#include <cmath>
#include <stdexcept>

namespace skybake {
namespace {

// Newton steps stop once a root moves by less than this: double precision
// near 1, so the weights (which depend on P_n' at the root) are exact to
// rounding.
constexpr double kRootTolerance = 1e-15;
// Newton from the asymptotic first guess converges in 3 to 5 steps; the cap
// only guards against a loop that never ends.
constexpr int kMaxNewtonSteps = 100;

struct LegendreValue {
  double p;           // P_n(x)
  double derivative;  // P_n'(x)
};

// P_n and its derivative by the three-term recurrence
// k P_k = (2k - 1) x P_{k-1} - (k - 1) P_{k-2}.
LegendreValue legendre(int n, double x) {
  double previous = 1.0;  // P_0
  double current = x;     // P_1
  for (int k = 2; k <= n; ++k) {
    const double next = ((2.0 * k - 1.0) * x * current - (k - 1.0) * previous) / k;
    previous = current;
    current = next;
  }
  // (x^2 - 1) P_n' = n (x P_n - P_{n-1}); the nodes lie strictly inside (-1, 1).
  return {current, n * (x * current - previous) / (x * x - 1.0)};
}

}  // namespace

GaussLegendreRule gaussLegendreRule(int n) {
  if (n < 1) throw std::invalid_argument("gaussLegendreRule: needs at least one node");
  GaussLegendreRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < n; ++i) {
    // The i-th largest root lies close to cos(pi (i + 3/4) / (n + 1/2)).
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
    LegendreValue v = legendre(n, x);
    for (int step = 0; step < kMaxNewtonSteps; ++step) {
      const double dx = v.p / v.derivative;
      x -= dx;
      v = legendre(n, x);
      if (std::abs(dx) < kRootTolerance) break;
    }
    // Store ascending: root i (descending) goes to n - 1 - i.
    rule.nodes[n - 1 - i] = x;
    rule.weights[n - 1 - i] = 2.0 / ((1.0 - x * x) * v.derivative * v.derivative);
  }
  return rule;
}

}  // namespace skybake
