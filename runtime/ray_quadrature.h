// Quadrature along a ray segment. Composite 4-point Gauss-Legendre: exact for
// polynomials of degree 7 on each sub-interval, so an exponential density
// whose scale height is comparable to a sub-interval is integrated to ~1e-4
// where the trapezoid rule with the same number of samples is percent-level
// off (it overestimates convex integrands).
#pragma once

namespace skybake {

inline constexpr int kGaussNodes = 4;
// Nodes on [-1, 1] and their weights.
inline constexpr double kGaussAbscissa[kGaussNodes] = {-0.8611363115940526, -0.3399810435848563,
                                                       0.3399810435848563, 0.8611363115940526};
inline constexpr double kGaussWeight[kGaussNodes] = {0.3478548451374538, 0.6521451548625461,
                                                     0.6521451548625461, 0.3478548451374538};

// Calls node(t, weight) for every node of a composite rule over [a, b] with
// `segments` equal sub-intervals; sum of weight * f(t) approximates the integral.
template <typename NodeFn>
inline void forEachQuadratureNode(double a, double b, int segments, NodeFn&& node) {
  const double h = (b - a) / segments;
  for (int s = 0; s < segments; ++s) {
    const double centre = a + (s + 0.5) * h;
    for (int k = 0; k < kGaussNodes; ++k) {
      node(centre + 0.5 * h * kGaussAbscissa[k], 0.5 * h * kGaussWeight[k]);
    }
  }
}

}  // namespace skybake

namespace skybake {

// Like forEachQuadratureNode over [0, length] of a ray, also giving each node
// the integral of `rate` (e.g. extinction) from 0 to the node: whole
// sub-intervals by the same rule, the partial one by a 4-point rule of its
// own. Calls node(t, weight, integral_to_t); returns the integral to `length`.
template <typename Value, typename RateFn, typename NodeFn>
inline Value forEachQuadratureNodeWithIntegral(double length, int segments, RateFn&& rate, NodeFn&& node) {
  const double h = length / segments;
  Value before(0.0);
  for (int s = 0; s < segments; ++s) {
    const double start = s * h;
    Value whole(0.0);
    for (int k = 0; k < kGaussNodes; ++k) {
      const double t = start + 0.5 * h * (1.0 + kGaussAbscissa[k]);
      const double partial_length = t - start;
      Value partial(0.0);
      for (int j = 0; j < kGaussNodes; ++j) {
        partial += rate(start + 0.5 * partial_length * (1.0 + kGaussAbscissa[j])) * (0.5 * partial_length * kGaussWeight[j]);
      }
      const Value rate_t = rate(t);
      whole += rate_t * (0.5 * h * kGaussWeight[k]);
      node(t, 0.5 * h * kGaussWeight[k], before + partial);
    }
    before += whole;
  }
  return before;
}

}  // namespace skybake
