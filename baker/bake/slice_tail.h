// The scattering orders after the last computed one, per (altitude, sun)
// slice of the scattering table.
//
// Each order is about a fixed fraction of the one before, the ratio tending
// to the scattering operator's largest eigenvalue; by day a slice's ratio
// reaches it within a few orders, so one ratio for the whole table (its
// mean radiance's, dominated by daylight) gives its remaining orders. In
// the planet's shadow the light of the first orders comes from far away and
// each order falls off more slowly at first: at the ground with the sun at
// 108 deg the 440 nm ratios are 1.40, 0.73, 0.55, 0.49 for orders 3 to 6
// against the table's 0.35, so the table's ratio leaves astronomical
// twilight 5 % short, and the slice's own last ratio, held for every later
// order, makes it 20 % too bright. Here each slice's ratio relaxes from its
// last one toward the table's by the factor seen between its last two
// (docs/MEASUREMENTS.md, "Orders").
#pragma once

#include <vector>

#include "data_formats/spectra/spectrum.h"
#include "runtime/tables/table_sampler.h"

namespace skybake {

// Beyond this relaxation factor per order a slice's ratio would stay away
// from the table's for tens of orders: a guess no computed order supports.
constexpr double kMaxRatioRelaxation = 0.9;

class SliceTail {
 public:
  // The slice means (entry i_r * mu_s_size + i_mu_s) of the last three
  // computed orders, oldest first, and the table's ratio per channel (each in
  // [0, max_ratio)); each slice's ratio is held below max_ratio.
  SliceTail(const TableSampler& sampler, const std::vector<SpectrumD>& before_previous,
            const std::vector<SpectrumD>& previous, const std::vector<SpectrumD>& last, const Spectrum& table_ratio,
            double max_ratio);

  // The remaining orders as a multiple of the last computed one, at slice
  // (i_r, i_mu_s) of the sampler the tail was made on.
  const Spectrum& scale(int i_r, int i_mu_s) const {
    return scale_[static_cast<size_t>(i_r) * sampler_.scatteringSizes().mu_s + i_mu_s];
  }
  // Every slice's, entry i_r * mu_s_size + i_mu_s (addReshaped's slice_scale).
  const std::vector<Spectrum>& scales() const { return scale_; }
  // The same at any radius (m) and sun cosine: bilinear between the slices
  // in the table's coordinates, clamped to its range (other tables' texels:
  // a narrowed scene's, the irradiance table's).
  Spectrum scaleAt(double r_m, double mu_s) const;
  // scaleAt at the slices of another sampler's tables (a narrowed scene's),
  // laid out as scales().
  std::vector<Spectrum> scalesAtSlicesOf(const TableSampler& other) const;
  // The largest multiple over every slice and channel (the bake report's).
  float largestScale() const;

 private:
  const TableSampler& sampler_;
  std::vector<Spectrum> scale_;
};

}  // namespace skybake
