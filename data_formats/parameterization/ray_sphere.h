// Distances from a point at radius r (metres from the planet centre) along a
// direction whose cosine with the local zenith is mu, to the spheres that
// bound the atmosphere: the kernel data_formats/kernel/shell_geometry.glsl
// in double, the one source the shaders share. The texture
// parameterization is built on these.
#pragma once

#include "data_formats/kernel/kernel_language.h"

namespace skybake {
namespace kernel {
#include "data_formats/kernel/shell_geometry.glsl"
}  // namespace kernel

// The kernel's functions under the C++ runtime's names.
inline constexpr auto& clampCosine = kernel::skybakeClampCosine;
inline constexpr auto& safeSqrt = kernel::skybakeSafeSqrt;
inline constexpr auto& distanceToOuterSphere = kernel::skybakeDistanceToOuterSphere;
inline constexpr auto& distanceToInnerSphere = kernel::skybakeDistanceToInnerSphere;
inline constexpr auto& distanceToAtmosphereEnd = kernel::skybakeDistanceToAtmosphereEnd;
inline constexpr auto& rayIntersectsSphere = kernel::skybakeRayIntersectsSphere;
inline constexpr auto& tangentZenithCosine = kernel::skybakeTangentZenithCosine;
inline constexpr auto& radiusAlongRay = kernel::skybakeRadiusAlongRay;
inline constexpr auto& cosineAlongRay = kernel::skybakeCosineAlongRay;

}  // namespace skybake
