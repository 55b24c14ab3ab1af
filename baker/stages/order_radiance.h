// How a stage reads the radiance of the order before it from the tables.
#pragma once

#include <vector>

#include "baker/stages/stage_context.h"
#include "data_formats/bake_file/textures.h"
#include "runtime/physics/multiple_scattering_phase.h"
#include "runtime/tables/table_sampler.h"

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
// With NuBlend::AsRadiance, at(nu) equals TableSampler::scattering of the
// order's tables at (r, mu, mu_s, nu) through OrderRadiance::withPhase.
//
// Across mu_s it blends as the runtime does (radianceBlend). Across nu too by
// default; NuBlend::Linear blends nu linearly whatever the sun. The
// scattering density, an integral over every incident direction, wants that:
// with the sun below the horizon the incident light peaks toward the sun's
// azimuth, and a geometric blend of a peak whose logarithm bends down
// (log-concave) falls short of it between every two nu slices, while a
// linear blend's errors change sign across the peak and largely cancel in
// the integral. Measured against finer tables, the default Earth's
// astronomical twilight sky went from -11 to -13 % mean (geometric) to +0.1
// to +0.7 %. The ground irradiance, also an integral, measured better with
// the runtime's blend (twilight sky irradiance 2.3 / 1.8 / 0.7 % against the
// reference; 8.0 / 7.7 / 6.8 % with the linear one in both stages) and
// keeps it.
enum class NuBlend { AsRadiance, Linear };

class OrderRadianceAlongNu {
 public:
  OrderRadianceAlongNu(const OrderRadiance& order, const TableSampler& sampler, double mie_g,
                       NuBlend nu_blend = NuBlend::AsRadiance)
      : order_(order), sampler_(sampler), mie_g_(mie_g), nu_blend_choice_(nu_blend) {}
  void moveTo(double r, double mu, double mu_s, bool ray_intersects_ground);
  Spectrum at(double nu) const;

 private:
  const OrderRadiance& order_;
  const TableSampler& sampler_;
  double mie_g_;
  NuBlend nu_blend_choice_;
  Blend blend_ = Blend::Linear;                 // across mu_s, at the current position
  Blend nu_blend_ = Blend::Linear;              // across nu, at the current position
  SpectrumD peak_weight_{0.0};                  // of the multiple-scattering shape, order >= 2
  std::vector<Spectrum> rayleigh_or_multiple_;  // per nu slice
  std::vector<Spectrum> mie_;                   // per nu slice, order 1
};

}  // namespace skybake
