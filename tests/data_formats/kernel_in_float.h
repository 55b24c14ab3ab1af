// Every kernel file (the order of SKYBAKE_KERNEL_GLSL_FILES) compiled as C++
// in float, as the shaders evaluate them, for the tests that compare them
// with the same text in double (the CPU runtime's and the bake's).
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "data_formats/kernel/kernel_language.h"

namespace kernel_in_float {
using Real = float;
using Real2 = glm::vec2;
using Real3 = glm::vec3;
// In the order of SKYBAKE_KERNEL_GLSL_FILES, which a file's dependencies
// follow.
// clang-format off
#include "data_formats/kernel/kernel_builtins.inc"
#include "data_formats/kernel/shell_geometry.glsl"
#include "data_formats/kernel/texture_coordinates.glsl"
#include "runtime/kernel/atmosphere_entry.glsl"
#include "runtime/kernel/phase_functions.glsl"
#include "runtime/kernel/multiple_scattering_shape.glsl"
#include "runtime/kernel/sun_disk.glsl"
#include "runtime/kernel/density_profile.glsl"
#include "runtime/kernel/table_weights.glsl"
#include "runtime/kernel/night_continuation.glsl"
#include "runtime/kernel/planet_shadow.glsl"
#include "runtime/kernel/moon_occlusion.glsl"
// clang-format on
}  // namespace kernel_in_float
