// The single-scattering tables: sunlight scattered once toward the viewer.
#pragma once

#include "baker/stages/stage_context.h"
#include "data_formats/bake_file/textures.h"
#include "runtime/physics/single_scattering_ray.h"

namespace skybake {

// Single scattering of sunlight, one ray integral per texel
// (integrateSingleScattering with the bake's rule). Rayleigh and Mie are kept
// apart, each without its phase function.
SingleScattering computeSingleScattering(const StageContext& ctx, const Texture2D& optical_depth, double r, double mu,
                                         double mu_s, double nu, bool ray_intersects_ground);
void computeSingleScatteringTables(const StageContext& ctx, const Texture2D& optical_depth, Texture4D& rayleigh,
                                   Texture4D& mie);

}  // namespace skybake
