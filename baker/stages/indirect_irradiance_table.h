// Ground irradiance from the sky light of one order.
#pragma once

#include "baker/stages/order_radiance.h"
#include "baker/stages/stage_context.h"

namespace skybake {

// Irradiance on a horizontal surface from the sky radiance of one order.
Texture2D computeIndirectIrradianceTable(const StageContext& ctx, const OrderRadiance& order);

}  // namespace skybake
