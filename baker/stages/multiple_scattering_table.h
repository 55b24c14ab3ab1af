// Multiple scattering of one order: its density integrated along each ray.
#pragma once

#include "baker/stages/stage_context.h"
#include "data_formats/textures.h"
#include "runtime/multiple_scattering_phase.h"

namespace skybake {

// Radiance of order n: the scattering density integrated along each ray,
// stored divided by the multiple-scattering shape at the texel's r and nu.
// Along a ray the sun's zenith angle changes, so each node reads the density
// between its sun texels. With the sun below the horizon there it reads a
// cubic in the density's logarithm across the sun axis
// (baker/numerics/log_cubic.h, which says why), linear elsewhere.
Texture4D computeMultipleScatteringTable(const StageContext& ctx, const Texture2D& optical_depth,
                                         const Texture4D& density, const MultipleScatteringPhase& shape);
// The same on ctx's texels from a density table on other texels (a scene's
// narrowed tables integrate the whole domain's density): `density_sampler`
// says where its texels are; the density is blended as above.
Texture4D computeMultipleScatteringTable(const StageContext& ctx, const Texture2D& optical_depth,
                                         const TableSampler& density_sampler, const Texture4D& density,
                                         const MultipleScatteringPhase& shape);

}  // namespace skybake
