// A scene that narrows the domain ([scene] ranges) gets its stored 4D tables
// on the narrowed texels. The orders still iterate over the whole domain:
// light reaching the scene's cameras was scattered at every altitude and
// under suns outside the scene's range, so the intermediate tables need it.
#pragma once

#include "baker/stages/stage_context.h"
#include "data_formats/bake_file/bake_file.h"
#include "runtime/physics/multiple_scattering_phase.h"

namespace skybake {

// Replaces the 4D tables of `tables` (single Rayleigh and Mie, multiple
// scattering and its density, the density on `whole`'s texels, every order
// summed)
// by the same quantities on `scene`'s texels: single scattering integrated
// anew, multiple scattering integrated from the whole domain's summed
// density, and `scene_density`, the density the bake computed on the scene's
// texels order by order. Multiple scattering and density are divided by
// `stored_shape`, as in the file.
void narrowTablesToScene(const StageContext& scene, const TableSampler& whole, const Texture2D& optical_depth,
                         const MultipleScatteringPhase& stored_shape, Texture4D scene_density, BakeTables& tables);

}  // namespace skybake
