// Scattering density: the source term of the next scattering order.
#pragma once

#include "baker/stages/order_radiance.h"
#include "baker/stages/scattering_density_kernel.h"
#include "baker/stages/stage_context.h"

namespace skybake {

// Light scattered once more at each point, per unit length (W m^-3 sr^-1 nm^-1),
// from the radiance of order n - 1 and, off the ground, the irradiance of
// order n - 2 (`ground_irradiance`), divided by order n's multiple-scattering
// `shape` at the texel's r and nu (runtime/physics/multiple_scattering_phase.h), on
// the texels of the stored density table: mu linear over [-1, 1] (see
// densityCoordMu). The multiple-scattering stage reads it there too: the
// density depends on the direction only and has no horizon split, and a
// second evaluation on the scattering table's texels (Bruneton's mu) changed
// no validated figure by more than 0.11 point while doubling this stage.
// `previous` is read through `previous_sampler`: ctx's own, or the whole
// domain's where ctx holds a scene's narrowed texels (the kernel is then
// the scene's, made on ctx).
Texture4D computeScatteringDensityTable(const StageContext& ctx, const ScatteringDensityKernel& kernel,
                                        const OrderRadiance& previous, const TableSampler& previous_sampler,
                                        const MultipleScatteringPhase& shape, const Texture2D& ground_irradiance);

}  // namespace skybake
