// Multiple scattering of one order: its density integrated along each ray.
#pragma once

#include "baker/stages/stage_context.h"
#include "data_formats/textures.h"
#include "runtime/multiple_scattering_phase.h"

namespace skybake {

// Radiance of order n: the scattering density integrated along each ray,
// stored divided by the multiple-scattering shape at the texel's r and nu.
Texture4D computeMultipleScatteringTable(const StageContext& ctx, const Texture2D& optical_depth,
                                         const Texture4D& density, const MultipleScatteringPhase& shape);
// The same on ctx's texels from a density table on other texels (a scene's
// narrowed tables integrate the whole domain's density): `density_sampler`
// says where its texels are. Its texels lie between the density's, where
// with the sun below the horizon the density falls by up to ten times from
// one sun texel to the next (2 to 3 deg apart in deep twilight) and a linear
// blend overestimates it by up to 1.7 times: there the density is blended
// across the sun axis as the runtime blends the tables (radianceBlend,
// geometric where steep). On its own texels (the orders) the blend stays
// linear.
Texture4D computeMultipleScatteringTable(const StageContext& ctx, const Texture2D& optical_depth,
                                         const TableSampler& density_sampler, const Texture4D& density,
                                         const MultipleScatteringPhase& shape);

}  // namespace skybake
