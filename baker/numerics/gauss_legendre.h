// Gauss-Legendre quadrature of any order: n nodes integrate polynomials of
// degree 2n - 1 exactly, so smooth integrands converge much faster than with
// equally spaced samples, and doubling n is a direct test of convergence.
#pragma once

#include <cstddef>
#include <vector>

namespace skybake {

// Nodes and weights on [-1, 1], nodes ascending.
struct GaussLegendreRule {
  std::vector<double> nodes;
  std::vector<double> weights;
};

// The n-node rule (n >= 1), nodes found as the roots of the Legendre
// polynomial P_n by Newton's method to double precision.
GaussLegendreRule gaussLegendreRule(int n);

// Calls node(x, weight) for each node of `rule` mapped onto [a, b]; the sum of
// weight * f(x) approximates the integral of f over [a, b].
template <typename NodeFn>
void forEachGaussLegendreNode(const GaussLegendreRule& rule, double a, double b, NodeFn&& node) {
  const double half = 0.5 * (b - a);
  const double centre = 0.5 * (a + b);
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) node(centre + half * rule.nodes[i], half * rule.weights[i]);
}

// The same over consecutive panels [edges[k], edges[k + 1]], each with the
// whole rule: the panels' edges are where the integrand has kinks or changes
// fast, which a single polynomial fit would smear.
template <typename NodeFn>
void forEachGaussLegendreNodeOnPanels(const GaussLegendreRule& rule, const std::vector<double>& edges, NodeFn&& node) {
  for (std::size_t k = 0; k + 1 < edges.size(); ++k) forEachGaussLegendreNode(rule, edges[k], edges[k + 1], node);
}

}  // namespace skybake
