#include "baker/bake/order_convergence.h"

#include <cmath>
#include <limits>

#include "data_formats/angles.h"
#include "data_formats/error.h"
#include "data_formats/parameterization/texture_mapping.h"
#include "runtime/physics/phase_functions.h"

namespace skybake {

std::vector<SpectrumD> sliceMeanSingleScatteringRadiance(const TableSampler& sampler, const Texture4D& rayleigh,
                                                         const Texture4D& mie, double g) {
  const ScatteringSizes& s = sampler.scatteringSizes();
  std::vector<SpectrumD> sum(static_cast<size_t>(s.r) * s.mu_s, SpectrumD(0.0));
  for (int i_r = 0; i_r < s.r; ++i_r)
    for (int i_mu = 0; i_mu < s.mu; ++i_mu)
      for (int i_mu_s = 0; i_mu_s < s.mu_s; ++i_mu_s)
        for (int i_nu = 0; i_nu < s.nu; ++i_nu) {
          const double nu = scatteringTexelConfig(sampler.domain(), s, i_r, i_mu, i_mu_s, i_nu).nu;
          sum[static_cast<size_t>(i_r) * s.mu_s + i_mu_s] +=
              SpectrumD(rayleigh.at(i_r, i_mu, i_mu_s, i_nu)) * rayleighPhase(nu) +
              SpectrumD(mie.at(i_r, i_mu, i_mu_s, i_nu)) * cornetteShanksPhase(g, nu);
        }
  for (SpectrumD& v : sum) v /= static_cast<double>(s.mu) * s.nu;
  return sum;
}

void OrderConvergence::add(const std::vector<SpectrumD>& slice_means) {
  if (total_.empty()) total_.assign(slice_means.size(), SpectrumD(0.0));
  if (slice_means.size() != total_.size()) throw Error(ErrorKind::Internal, "OrderConvergence: slices differ");
  for (size_t i = 0; i < total_.size(); ++i) total_[i] += slice_means[i];
  history_.push_back(slice_means);
}

const std::vector<SpectrumD>& OrderConvergence::sliceMeans(size_t from_last) const {
  if (from_last >= history_.size()) throw Error(ErrorKind::Internal, "OrderConvergence: no such order");
  return history_[history_.size() - 1 - from_last];
}

SliceShare OrderConvergence::worstLastShare() const {
  SliceShare worst;
  if (history_.empty()) return worst;
  const std::vector<SpectrumD>& last = history_.back();
  const ScatteringSizes& s = sampler_.scatteringSizes();
  for (size_t i = 0; i < last.size(); ++i) {
    for (int c = 0; c < channels_; ++c) {
      double share = 0.0;
      if (!std::isfinite(total_[i][c]) || !std::isfinite(last[i][c])) {
        share = std::numeric_limits<double>::infinity();
      } else if (total_[i][c] > 0.0) {
        share = last[i][c] / total_[i][c];
      }
      if (share <= worst.share) continue;
      const int i_r = static_cast<int>(i / s.mu_s);
      const int i_mu_s = static_cast<int>(i % s.mu_s);
      worst.share = share;
      worst.altitude_m = rFromScatteringTexel(sampler_.domain(), s, i_r) - sampler_.domain().bottom_radius_m;
      worst.sun_zenith_deg = degreesFromRadians(std::acos(muSFromScatteringTexel(sampler_.domain(), s, i_mu_s)));
    }
  }
  return worst;
}

}  // namespace skybake
