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
