// How much of the sun disk a point sees above the planet's horizon: the
// kernel runtime/kernel/sun_disk.glsl in double, the one source the shaders
// share.
#pragma once

#include "data_formats/kernel/kernel_language.h"

namespace skybake {
namespace kernel {
#include "runtime/kernel/sun_disk.glsl"
}  // namespace kernel

inline constexpr auto& sunDiskVisibleFraction = kernel::skybakeSunDiskVisibleFraction;
inline constexpr auto& sunDiskHalfSizeAtHorizon = kernel::skybakeSunDiskHalfSizeAtHorizon;

}  // namespace skybake
