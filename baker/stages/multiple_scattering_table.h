// Multiple scattering of one order: its density integrated along each ray.
#pragma once

#include "baker/stages/stage_context.h"
#include "data_formats/bake_file/textures.h"
#include "runtime/physics/multiple_scattering_phase.h"

namespace skybake {

// Sub-intervals of each ray's 4-point Gauss-Legendre rule
// (runtime/physics/ray_quadrature.h; optically thick ones are split further). The
// density varies smoothly along a ray, falling with the constituents' scale
// heights. The stored table: against 8 sub-intervals, 4 moved the default
// bake's sky radiance, ground rays, rays to points and sky irradiance by at
// most 0.02 % RMS in every sun band (docs/MEASUREMENTS.md, "Orders on
// coarser tables").
inline constexpr int kStoredRaySegments = 4;
// An order's radiance while the orders iterate feeds only the next order's
// density, an integral over every direction: 2 sub-intervals moved the
// stored tables by at most 0.03 % RMS against 4.
inline constexpr int kOrderRadianceRaySegments = 2;

// Radiance of order n: the scattering density integrated along each ray,
// stored divided by the multiple-scattering shape at the texel's r and nu.
// Along a ray the sun's zenith angle changes, so each node reads the density
// between its sun texels. With the sun below the horizon there it reads a
// cubic in the density's logarithm across the sun axis
// (baker/numerics/log_cubic.h, which says why), linear elsewhere. The table
// is on ctx's texels, the density on `density_sampler`'s (the whole
// domain's for a scene's narrowed tables; the finer stored density for an
// order's radiance while iterating); each ray is integrated on
// `ray_segments` sub-intervals (above).
Texture4D computeMultipleScatteringTable(const StageContext& ctx, const Texture2D& optical_depth,
                                         const TableSampler& density_sampler, const Texture4D& density,
                                         const MultipleScatteringPhase& shape, int ray_segments);

}  // namespace skybake
