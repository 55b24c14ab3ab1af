// How far a bake's scattering orders are from converged, measured where they
// converge slowest. Over the whole table the orders fall off fast (daylight
// dominates its mean), but in the planet's shadow the light has scattered
// many times and each order falls off more slowly: at the ground with the
// sun 18 deg below the horizon the fourth order still adds a fifth of the
// light at 440 nm. So the share of the last order is taken per (altitude,
// sun) slice of the scattering table, and the worst slice decides.
#pragma once

#include <vector>

#include "data_formats/bake_file/textures.h"
#include "data_formats/spectra/spectrum.h"
#include "runtime/tables/table_sampler.h"

namespace skybake {

// Mean single-scattering radiance of each (r, mu_s) slice of the tables (all
// mu and nu), phase functions applied: entry i_r * mu_s_size + i_mu_s.
std::vector<SpectrumD> sliceMeanSingleScatteringRadiance(const TableSampler& sampler, const Texture4D& rayleigh,
                                                         const Texture4D& mie, double g);

struct SliceShare {
  double share = 0.0;  // the last order's share of the slice's total, worst channel
  double altitude_m = 0.0;
  double sun_zenith_deg = 0.0;
};

class OrderConvergence {
 public:
  OrderConvergence(const TableSampler& sampler, int channels) : sampler_(sampler), channels_(channels) {}
  // One more order's mean radiance per slice (orders in sequence from 1).
  void add(const std::vector<SpectrumD>& slice_means);
  // The last order's share of the total so far in the slice where it is
  // largest. A slice with no light has converged trivially; a non-finite
  // mean never has (share infinity).
  SliceShare worstLastShare() const;
  // The slice means of the order `from_last` orders before the last added
  // (0: the last); needs that many orders added before it.
  const std::vector<SpectrumD>& sliceMeans(size_t from_last) const;

 private:
  const TableSampler& sampler_;
  int channels_;
  std::vector<SpectrumD> total_;
  std::vector<std::vector<SpectrumD>> history_;  // every order's slice means, first order first
};

}  // namespace skybake
