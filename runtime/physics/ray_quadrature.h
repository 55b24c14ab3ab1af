// Quadrature along a ray segment. Composite 4-point Gauss-Legendre: exact for
// polynomials of degree 7 on each sub-interval, so an exponential density
// whose scale height is comparable to a sub-interval is integrated to ~1e-4
// where the trapezoid rule with the same number of samples is percent-level
// off (it overestimates convex integrands).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace skybake {

inline constexpr int kGaussNodes = 4;
// Nodes on [-1, 1] and their weights.
inline constexpr double kGaussAbscissa[kGaussNodes] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                                       0.8611363115940526};
inline constexpr double kGaussWeight[kGaussNodes] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                                     0.3478548451374538};

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

// Splitting sub-intervals that are optically thick. Composite rules with a
// fixed number of sub-intervals assume the transmittance changes little
// across each; in fog or a dense planet a sub-interval can hold tens of mean
// free paths, where the 4-point rule misses most of exp(-tau): over tau in
// [0, 3] it is 3e-6 low, over [0, 16] 6 % low, over [0, 60] a factor 10.

// Largest optical depth (in the channel with the largest extinction) one
// 4-point rule covers.
inline constexpr double kMaxPieceOpticalDepth = 3.0;
// Past this optical depth from the start nothing is split any more: light
// from there is dimmed by e^-40 = 4e-18, below float resolution of the light
// from nearer, so a coarse rule there costs nothing visible.
inline constexpr double kRefinedOpticalDepth = 40.0;
// Most pieces one sub-interval is split into: bounds the work when the
// extinction is beyond any atmosphere's (a kilometre of 1e-1 m^-1).
inline constexpr int kMaxPiecesPerSubinterval = 256;

// No bound known on the extinction along a ray (forEachOpticallyThinPiece).
inline constexpr double kNoExtinctionBound = std::numeric_limits<double>::infinity();

// Calls piece(start, end) for `segments` equal sub-intervals of [a, b], each
// split into equal pieces of at most kMaxPieceOpticalDepth until the optical
// depth from a passes kRefinedOpticalDepth. `extinction(t)` is the largest
// channel's extinction (m^-1) at distance t; a sub-interval's peak is taken
// as the largest of it at the ends, the middle and the ray's lowest point
// `lowest_t` where that lies inside (profiles that peak between are caught
// by the middle, not guaranteed). The optical depth travelled is estimated
// from each piece's middle. `extinction_bound_per_m`, when given, is at least
// every value `extinction` returns (AtmosphereMedia::largestExtinctionBound):
// where it shows no sub-interval can be split, the sub-intervals are the
// pieces at once, as the peaks would have decided, and `extinction` is not
// called (most rays of an Earth-like sky are that thin).
template <typename ExtinctionFn, typename PieceFn>
inline void forEachOpticallyThinPiece(double a, double b, int segments, double lowest_t, ExtinctionFn&& extinction,
                                      PieceFn&& piece, double extinction_bound_per_m = kNoExtinctionBound) {
  const double h = (b - a) / segments;
  auto subintervalEnd = [&](int s, double start) { return s + 1 == segments ? b : start + h; };
  bool all_thin = extinction_bound_per_m < kNoExtinctionBound;
  for (int s = 0; s < segments && all_thin; ++s) {
    const double start = a + s * h;
    all_thin = extinction_bound_per_m * (subintervalEnd(s, start) - start) <= kMaxPieceOpticalDepth;
  }
  if (all_thin) {
    for (int s = 0; s < segments; ++s) {
      const double start = a + s * h;
      piece(start, subintervalEnd(s, start));
    }
    return;
  }
  double depth = 0.0;
  // In double whatever the callable returns; each sub-interval's end is the
  // next one's start.
  auto extinctionAt = [&](double t) -> double { return extinction(t); };
  double extinction_start = extinctionAt(a);
  for (int s = 0; s < segments; ++s) {
    const double start = a + s * h;
    const double end = subintervalEnd(s, start);
    if (!(depth < kRefinedOpticalDepth)) {
      piece(start, end);
      continue;
    }
    const double extinction_end = extinctionAt(end);
    double peak = std::max({extinction_start, extinctionAt(0.5 * (start + end)), extinction_end});
    if (lowest_t > start && lowest_t < end) peak = std::max(peak, extinctionAt(lowest_t));
    extinction_start = extinction_end;
    // Also false for a NaN or infinite peak: one piece, whose nodes show it.
    if (!(peak * (end - start) > kMaxPieceOpticalDepth && std::isfinite(peak))) {
      piece(start, end);
      depth += peak * (end - start);
      continue;
    }
    const int count = static_cast<int>(
        std::min<double>(kMaxPiecesPerSubinterval, std::ceil(peak * (end - start) / kMaxPieceOpticalDepth)));
    const double step = (end - start) / count;
    for (int k = 0; k < count; ++k) {
      const double piece_start = start + k * step;
      if (!(depth < kRefinedOpticalDepth)) {
        piece(piece_start, end);
        break;
      }
      const double piece_end = k + 1 == count ? end : piece_start + step;
      piece(piece_start, piece_end);
      depth += extinctionAt(0.5 * (piece_start + piece_end)) * (piece_end - piece_start);
    }
  }
}

// forEachQuadratureNode with optically thick sub-intervals split
// (forEachOpticallyThinPiece): calls node(t, weight).
template <typename ExtinctionFn, typename NodeFn>
inline void forEachOpticallyThinNode(double a, double b, int segments, double lowest_t, ExtinctionFn&& extinction,
                                     NodeFn&& node, double extinction_bound_per_m = kNoExtinctionBound) {
  forEachOpticallyThinPiece(
      a, b, segments, lowest_t, extinction,
      [&](double start, double end) { forEachQuadratureNode(start, end, 1, node); }, extinction_bound_per_m);
}

// forEachOpticallyThinNode with each piece also cut at the distances
// `cuts` (ascending; those outside a piece are ignored) and every part given
// its own 4-point rule: for an integrand that jumps at the cuts (the edges of
// the planet's shadow). The pieces come from [a, b] alone, so as a cut moves
// (the sun sinks) the nodes move with it continuously: a part shrinks to
// nothing as the cut reaches a piece's end and grows from nothing past it.
// Giving each stretch between cuts its own share of `segments` instead
// (rounded to whole sub-intervals) made the integral jump, by up to 1 % of a
// grazing twilight ray, each time a share crossed a whole number.
// The parts of the piece [start, end] between the distances `cuts`
// (ascending; those outside it are ignored): calls part(part_start, part_end)
// in order, once with the whole piece where no cut falls inside it.
template <typename PartFn>
inline void forEachPartCutAt(double start, double end, const double* cuts, int cut_count, PartFn&& part) {
  double part_start = start;
  for (int i = 0; i < cut_count; ++i) {
    if (cuts[i] > part_start && cuts[i] < end) {
      part(part_start, cuts[i]);
      part_start = cuts[i];
    }
  }
  part(part_start, end);
}

// Parts for which `zero(part_start, part_end)` holds are skipped: the
// integrand is known to be 0 on them (a stretch the planet's shadow hides
// the whole sun from, sunless_segment.h).
template <typename ExtinctionFn, typename ZeroFn, typename NodeFn>
inline void forEachOpticallyThinNodeCutAt(double a, double b, int segments, double lowest_t, const double* cuts,
                                          int cut_count, ExtinctionFn&& extinction, ZeroFn&& zero, NodeFn&& node,
                                          double extinction_bound_per_m = kNoExtinctionBound) {
  forEachOpticallyThinPiece(
      a, b, segments, lowest_t, extinction,
      [&](double start, double end) {
        forEachPartCutAt(start, end, cuts, cut_count, [&](double part_start, double part_end) {
          if (!zero(part_start, part_end)) forEachQuadratureNode(part_start, part_end, 1, node);
        });
      },
      extinction_bound_per_m);
}

// Like forEachOpticallyThinNode over [0, length] of a ray, also giving each
// node the integral of `rate` (a spectrum, e.g. extinction) from 0 to the
// node: whole pieces by the same rule, the partial one by a 4-point rule of
// its own. `largest` reduces a rate to the scalar the pieces are split by.
// Calls node(t, weight, integral_to_t); returns the integral to `length`.
template <typename Value, typename RateFn, typename LargestFn, typename NodeFn>
inline Value forEachOpticallyThinNodeWithIntegral(double length, int segments, double lowest_t, RateFn&& rate,
                                                  LargestFn&& largest, NodeFn&& node) {
  Value before(0.0);
  forEachOpticallyThinPiece(
      0.0, length, segments, lowest_t, [&](double t) { return largest(rate(t)); },
      [&](double start, double end) {
        const double h = end - start;
        Value whole(0.0);
        for (int k = 0; k < kGaussNodes; ++k) {
          const double t = start + 0.5 * h * (1.0 + kGaussAbscissa[k]);
          const double partial_length = t - start;
          Value partial(0.0);
          for (int j = 0; j < kGaussNodes; ++j) {
            partial += rate(start + 0.5 * partial_length * (1.0 + kGaussAbscissa[j])) *
                       (0.5 * partial_length * kGaussWeight[j]);
          }
          whole += rate(t) * (0.5 * h * kGaussWeight[k]);
          node(t, 0.5 * h * kGaussWeight[k], before + partial);
        }
        before += whole;
      });
  return before;
}

}  // namespace skybake
