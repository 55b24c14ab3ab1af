// The bake stages (Bruneton 2017). Each fills a table from earlier tables;
// each texel is computed independently, so the result does not depend on how
// texels are spread over threads.
#pragma once

#include <vector>

#include "baker/progress.h"
#include "data_formats/bake_file.h"
#include "runtime/multiple_scattering_phase.h"
#include "runtime/single_scattering_ray.h"
#include "runtime/table_sampler.h"

namespace skybake {

struct StageContext {
  const AtmosphereParameters& atmosphere;
  const TableSampler& sampler;
  ProgressSink& progress;
};

// Optical depth to the top boundary for every (r, mu) texel.
Texture2D computeTransmittanceTable(const StageContext& ctx);

// Irradiance from the sun (attenuated, disk partly below the horizon
// included) on a horizontal surface at every (r, mu_s) texel.
Texture2D computeDirectIrradianceTable(const StageContext& ctx, const Texture2D& optical_depth);

// Single scattering of sunlight, one ray integral per texel
// (integrateSingleScattering with the bake's rule). Rayleigh and Mie are kept
// apart, each without its phase function.
SingleScattering computeSingleScattering(const StageContext& ctx, const Texture2D& optical_depth,
                                         double r, double mu, double mu_s, double nu,
                                         bool ray_intersects_ground);
void computeSingleScatteringTables(const StageContext& ctx, const Texture2D& optical_depth,
                                   Texture4D& rayleigh, Texture4D& mie);

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
  Spectrum withPhase(const Spectrum& rayleigh_or_multiple, const Spectrum& mie, double nu,
                     const SpectrumD& peak_weight, double mie_g) const;
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
  SpectrumD peak_weight_{0.0};             // of the multiple-scattering shape, order >= 2
  std::vector<Spectrum> rayleigh_or_multiple_;  // per nu slice
  std::vector<Spectrum> mie_;                   // per nu slice, order 1
};

// Light scattered once more at each point, per unit length (W m^-3 sr^-1 nm^-1),
// from the radiance of order n - 1 and, off the ground, the irradiance of
// order n - 2 (`ground_irradiance`), divided by order n's multiple-scattering
// `shape` at the texel's r and nu (runtime/multiple_scattering_phase.h), on
// the texels of the stored density table: mu linear over [-1, 1] (see
// densityCoordMu). The multiple-scattering stage reads it there too: the
// density depends on the direction only and has no horizon split, and a
// second evaluation on the scattering table's texels (Bruneton's mu) changed
// no validated figure by more than 0.11 point while doubling this stage.
// `previous` is read through `previous_sampler`: ctx's own, or the whole
// domain's where ctx holds a scene's narrowed texels (the kernel is then
// the scene's, made on ctx).
struct ScatteringDensityKernel;  // baker/scattering_density_kernel.h: built once per bake
Texture4D computeScatteringDensityTable(const StageContext& ctx, const ScatteringDensityKernel& kernel,
                                        const OrderRadiance& previous, const TableSampler& previous_sampler,
                                        const MultipleScatteringPhase& shape, const Texture2D& ground_irradiance);

// Irradiance on a horizontal surface from the sky radiance of one order.
Texture2D computeIndirectIrradianceTable(const StageContext& ctx, const OrderRadiance& order);

// Radiance of order n: the scattering density integrated along each ray,
// stored divided by the multiple-scattering shape at the texel's r and nu.
Texture4D computeMultipleScatteringTable(const StageContext& ctx, const Texture2D& optical_depth,
                                         const Texture4D& density, const MultipleScatteringPhase& shape);
// The same on ctx's texels from a density table on other texels (a scene's
// narrowed tables integrate the whole domain's density): `density_sampler`
// says where its texels are.
Texture4D computeMultipleScatteringTable(const StageContext& ctx, const Texture2D& optical_depth,
                                         const TableSampler& density_sampler, const Texture4D& density,
                                         const MultipleScatteringPhase& shape);

}  // namespace skybake
