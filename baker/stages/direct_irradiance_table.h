// Ground irradiance from the sun, attenuated on its way down.
#pragma once

#include "baker/stages/stage_context.h"
#include "data_formats/bake_file/textures.h"

namespace skybake {

// Irradiance from the sun (attenuated, disk partly below the horizon
// included) on a horizontal surface at every (r, mu_s) texel.
Texture2D computeDirectIrradianceTable(const StageContext& ctx, const Texture2D& optical_depth);

}  // namespace skybake
