// How a stage reads the radiance of the order before it from the tables.
#pragma once

#include <vector>

#include "baker/stages/stage_context.h"
#include "data_formats/textures.h"
#include "runtime/multiple_scattering_phase.h"
#include "runtime/table_sampler.h"

namespace skybake {

// The radiance of one scattering order arriving at a point, seen looking in a
// direction: single scattering with its phase functions applied for order 1,
// that order's table times the multiple-scattering shape after that.
struct OrderRadiance {
  int order;  // the scattering order whose radiance this gives, >= 1
  const Texture4D& single_rayleigh;
  const Texture4D& single_mie;
  const Texture4D& multiple;  // that order's table when order >= 2 (divided, as stored)
  const MultipleScatteringPhase& multiple_shape;
  // The radiance from the tables' values at a lookup (OrderRadianceAlongNu): order 1 weights the
  // single Rayleigh and Mie values by their phase functions at nu, later
  // orders multiply the table's value (`rayleigh_or_multiple`; `mie` unused)
  // by the shape with the lookup altitude's peak weight.
  Spectrum withPhase(const Spectrum& rayleigh_or_multiple, const Spectrum& mie, double nu, const SpectrumD& peak_weight,
                     double mie_g) const;
};

// The radiance of one order at a fixed (r, mu, mu_s), for any nu: the tables
// are interpolated on each of their nu slices once (moveTo), so each nu then
// costs one blend and the phase functions instead of a 16-texel lookup.
// at(nu) equals TableSampler::scattering of the order's tables at
// (r, mu, mu_s, nu) through OrderRadiance::withPhase.
class OrderRadianceAlongNu {
 public:
  OrderRadianceAlongNu(const OrderRadiance& order, const TableSampler& sampler, double mie_g)
      : order_(order), sampler_(sampler), mie_g_(mie_g) {}
  void moveTo(double r, double mu, double mu_s, bool ray_intersects_ground);
  Spectrum at(double nu) const;

 private:
  const OrderRadiance& order_;
  const TableSampler& sampler_;
  double mie_g_;
  Blend blend_ = Blend::Linear;
  SpectrumD peak_weight_{0.0};                  // of the multiple-scattering shape, order >= 2
  std::vector<Spectrum> rayleigh_or_multiple_;  // per nu slice
  std::vector<Spectrum> mie_;                   // per nu slice, order 1
};

}  // namespace skybake
