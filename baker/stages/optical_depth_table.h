// The first stage: the optical-depth table (Bruneton 2017 stores
// transmittance; skybake stores its optical depth, data_formats/FORMAT.md).
#pragma once

#include "baker/stages/stage_context.h"
#include "data_formats/bake_file/textures.h"

namespace skybake {

// Optical depth to the top boundary for every (r, mu) texel.
Texture2D computeOpticalDepthTable(const StageContext& ctx);

}  // namespace skybake
