// Ground irradiance from the sky light of one order.
#pragma once

#include "baker/stages/order_radiance.h"
#include "baker/stages/stage_context.h"

namespace skybake {

// Irradiance on a horizontal surface from the sky radiance of one order.
// `optical_depth` is the transmittance stage's table, for order 1's single
// scattering integrated along the view rays with the sun below the horizon.
Texture2D computeIndirectIrradianceTable(const StageContext& ctx, const Texture2D& optical_depth,
                                         const OrderRadiance& order);

}  // namespace skybake
