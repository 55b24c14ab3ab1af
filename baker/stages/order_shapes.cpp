#include "baker/stages/order_shapes.h"

#include <vector>

#include <glm/geometric.hpp>

#include "data_formats/error.h"

namespace skybake {
namespace {

// Calls f(i_r, i_mu, i_mu_s, i_nu, nu) for every texel, nu being the one the
// texel was computed for (its slice's, clamped to the range its mu and mu_s
// allow). Altitude rows run on the OpenMP threads, each row's texels in
// order on one thread: f may write its texel and accumulate into sums of
// its own altitude, and such sums add in the same order for any thread count.
template <typename F>
void forEachTexel(const TableSampler& sampler, TexelLayout layout, F&& f) {
  const AtmosphereDomain& d = sampler.domain();
  const ScatteringSizes& s = sampler.scatteringSizes();
  std::vector<double> mu_s_of_texel(s.mu_s);
  for (int i_mu_s = 0; i_mu_s < s.mu_s; ++i_mu_s) mu_s_of_texel[i_mu_s] = muSFromScatteringTexel(d, s, i_mu_s);
#pragma omp parallel for schedule(static)
  for (int i_r = 0; i_r < s.r; ++i_r) {
    for (int i_mu = 0; i_mu < s.mu; ++i_mu) {
      const double mu = layout == TexelLayout::Scattering ? scatteringTexelConfig(d, s, i_r, i_mu, 0, 0).mu
                                                          : muFromDensityTexel(i_mu, s.mu);
      for (int i_mu_s = 0; i_mu_s < s.mu_s; ++i_mu_s) {
        for (int i_nu = 0; i_nu < s.nu; ++i_nu) {
          f(i_r, i_mu, i_mu_s, i_nu, clampNu(nuOfScatteringSlice(i_nu, s.nu), mu, mu_s_of_texel[i_mu_s]));
        }
      }
    }
  }
}

// The shape's peak weight at each r texel.
std::vector<SpectrumD> peakWeightsOfRows(const TableSampler& sampler, const MultipleScatteringPhase& shape) {
  const ScatteringSizes& s = sampler.scatteringSizes();
  std::vector<SpectrumD> w(s.r);
  for (int i_r = 0; i_r < s.r; ++i_r) {
    w[i_r] = shape.peakWeightAt(rFromScatteringTexel(sampler.domain(), s, i_r) - sampler.domain().bottom_radius_m);
  }
  return w;
}

}  // namespace

std::vector<SpectrumD> sliceMeanShapedRadiance(const TableSampler& sampler, const Texture4D& table,
                                               const MultipleScatteringPhase& shape) {
  const ScatteringSizes& s = sampler.scatteringSizes();
  const std::vector<SpectrumD> weight = peakWeightsOfRows(sampler, shape);
  std::vector<SpectrumD> sum(static_cast<size_t>(s.r) * s.mu_s, SpectrumD(0.0));  // long sums: double
  forEachTexel(sampler, TexelLayout::Scattering, [&](int i_r, int i_mu, int i_mu_s, int i_nu, double nu) {
    sum[static_cast<size_t>(i_r) * s.mu_s + i_mu_s] +=
        SpectrumD(table.at(i_r, i_mu, i_mu_s, i_nu) * shape(weight[i_r], nu));
  });
  for (SpectrumD& v : sum) v /= static_cast<double>(s.mu) * s.nu;
  return sum;
}

void addReshaped(const TableSampler& sampler, TexelLayout layout, const Texture4D& delta,
                 const MultipleScatteringPhase& from, const MultipleScatteringPhase& to, const Spectrum& scale,
                 Texture4D& sum) {
  if (sum.texels.size() != delta.texels.size()) {
    throw Error(ErrorKind::Internal, "addReshaped: tables of different sizes");
  }
  if (from.order() == to.order()) {
    const ptrdiff_t n = static_cast<ptrdiff_t>(sum.texels.size());
#pragma omp parallel for schedule(static)
    for (ptrdiff_t i = 0; i < n; ++i) sum.texels[i] += delta.texels[i] * scale;
    return;
  }
  const ScatteringSizes& s = sampler.scatteringSizes();
  addReshaped(sampler, layout, delta, from, to, std::vector<Spectrum>(static_cast<size_t>(s.r) * s.mu_s, scale), sum);
}

void addReshaped(const TableSampler& sampler, TexelLayout layout, const Texture4D& delta,
                 const MultipleScatteringPhase& from, const MultipleScatteringPhase& to,
                 const std::vector<Spectrum>& slice_scale, Texture4D& sum) {
  const ScatteringSizes& s = sampler.scatteringSizes();
  if (sum.texels.size() != delta.texels.size() || slice_scale.size() != static_cast<size_t>(s.r) * s.mu_s) {
    throw Error(ErrorKind::Internal, "addReshaped: tables of different sizes");
  }
  const std::vector<SpectrumD> from_weight = peakWeightsOfRows(sampler, from);
  const std::vector<SpectrumD> to_weight = peakWeightsOfRows(sampler, to);
  forEachTexel(sampler, layout, [&](int i_r, int i_mu, int i_mu_s, int i_nu, double nu) {
    sum.at(i_r, i_mu, i_mu_s, i_nu) += delta.at(i_r, i_mu, i_mu_s, i_nu) *
                                       slice_scale[static_cast<size_t>(i_r) * s.mu_s + i_mu_s] *
                                       from(from_weight[i_r], nu) / to(to_weight[i_r], nu);
  });
}

void addMixedReshaped(const TableSampler& sampler, TexelLayout layout, const Texture4D& delta,
                      const MultipleScatteringPhase& from, const MultipleScatteringPhase& to,
                      const std::array<Spectrum, kMaxChannels>& mix, Texture4D& sum) {
  if (sum.texels.size() != delta.texels.size()) {
    throw Error(ErrorKind::Internal, "addMixedReshaped: tables of different sizes");
  }
  const std::vector<SpectrumD> from_weight = peakWeightsOfRows(sampler, from);
  const std::vector<SpectrumD> to_weight = peakWeightsOfRows(sampler, to);
  forEachTexel(sampler, layout, [&](int i_r, int i_mu, int i_mu_s, int i_nu, double nu) {
    const Spectrum radiance = delta.at(i_r, i_mu, i_mu_s, i_nu) * from(from_weight[i_r], nu);
    const Spectrum divisor = to(to_weight[i_r], nu);  // > 0 in every lane
    Spectrum& out = sum.at(i_r, i_mu, i_mu_s, i_nu);
    for (int c = 0; c < kMaxChannels; ++c) out[c] += glm::dot(mix[c], radiance) / divisor[c];
  });
}

}  // namespace skybake
