#include "baker/bake/slice_tail.h"

#include <algorithm>
#include <cmath>

#include "data_formats/parameterization/texture_mapping.h"

namespace skybake {
namespace {

// The series stops where an order adds less than this share of the sum so
// far: float tables hold 6e-8 of a value, so smaller terms change nothing.
constexpr double kNegligibleTermShare = 1e-8;
// The series has terms below r_max^k, r_max < 1; this many keeps any ratio
// up to 0.9 to 1e-8 and bounds the work for any input.
constexpr int kMaxTailTerms = 200;

// Orders after the last, as a multiple of it: r_k relaxes toward r_table by
// `relaxation` per order, each order r_k times the one before.
double relaxedSeriesSum(double last_ratio, double table_ratio, double relaxation, double max_ratio) {
  double ratio = last_ratio, term = 1.0, sum = 0.0;
  for (int k = 0; k < kMaxTailTerms; ++k) {
    ratio = std::clamp(table_ratio + (ratio - table_ratio) * relaxation, 0.0, max_ratio);
    term *= ratio;
    sum += term;
    if (term <= kNegligibleTermShare * sum) break;
  }
  return sum;
}

}  // namespace

SliceTail::SliceTail(const TableSampler& sampler, const std::vector<SpectrumD>& before_previous,
                     const std::vector<SpectrumD>& previous, const std::vector<SpectrumD>& last,
                     const Spectrum& table_ratio, double max_ratio)
    : sampler_(sampler), scale_(last.size(), Spectrum(0.0f)) {
  for (size_t i = 0; i < last.size(); ++i) {
    for (int c = 0; c < kMaxChannels; ++c) {
      const double r_table = table_ratio[c];
      // Without light in the two orders before, a slice has no ratios of its
      // own: the table's holds from the first remaining order on.
      double last_ratio = r_table, relaxation = 0.0;
      if (previous[i][c] > 0.0 && before_previous[i][c] > 0.0) {
        last_ratio = last[i][c] / previous[i][c];
        const double previous_ratio = previous[i][c] / before_previous[i][c];
        const double excess = last_ratio - r_table, previous_excess = previous_ratio - r_table;
        // Ratios moving toward the table's from one side relax; any other
        // history (crossing it, moving away) is not a trend to extrapolate.
        if (excess * previous_excess > 0.0 && std::abs(excess) < std::abs(previous_excess)) {
          relaxation = std::min(excess / previous_excess, kMaxRatioRelaxation);
        }
      }
      scale_[i][c] = static_cast<float>(relaxedSeriesSum(last_ratio, r_table, relaxation, max_ratio));
    }
  }
}

Spectrum SliceTail::scaleAt(double r_m, double mu_s) const {
  const AtmosphereDomain& d = sampler_.domain();
  const ScatteringSizes& s = sampler_.scatteringSizes();
  const AxisLerp r = axisLerpFromTextureCoord(scatteringCoordR(d, s.r, d.distanceToHorizon(r_m)), s.r);
  const AxisLerp m = axisLerpFromTextureCoord(scatteringCoordMuS(d, s.mu_s, mu_s), s.mu_s);
  return (scale(r.i0, m.i0) * (1.0f - m.w1) + scale(r.i0, m.i1) * m.w1) * (1.0f - r.w1) +
         (scale(r.i1, m.i0) * (1.0f - m.w1) + scale(r.i1, m.i1) * m.w1) * r.w1;
}

std::vector<Spectrum> SliceTail::scalesAtSlicesOf(const TableSampler& other) const {
  const AtmosphereDomain& d = other.domain();
  const ScatteringSizes& s = other.scatteringSizes();
  std::vector<Spectrum> out(static_cast<size_t>(s.r) * s.mu_s);
  for (int i_r = 0; i_r < s.r; ++i_r)
    for (int i_mu_s = 0; i_mu_s < s.mu_s; ++i_mu_s)
      out[static_cast<size_t>(i_r) * s.mu_s + i_mu_s] =
          scaleAt(rFromScatteringTexel(d, s, i_r), muSFromScatteringTexel(d, s, i_mu_s));
  return out;
}

float SliceTail::largestScale() const {
  float largest = 0.0f;
  for (const Spectrum& s : scale_)
    for (int c = 0; c < kMaxChannels; ++c) largest = std::max(largest, s[c]);
  return largest;
}

}  // namespace skybake
