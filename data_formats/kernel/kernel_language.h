// The C++ side of skybake's kernel language. A kernel file (*.glsl in
// data_formats/kernel/ and runtime/kernel/) holds formulas the CPU and the
// shaders both evaluate, written once in the subset of GLSL that is also
// C++: functions marked SKYBAKE_KERNEL and named skybake*, the scalar type
// Real and the vector types Real2 and Real3, the built-ins of kernel_builtins.inc and
// the constant SKYBAKE_PI; no `const` locals (GLSL ES needs constant
// expressions there), no struct constructors (members are set one by one),
// no out parameters, float literals written with a point (0.0).
//
// C++ reads a kernel file inside a namespace that names Real and Real3:
// skybake::kernel below, in double, for the runtime and the bake (each
// kernel file has a header that includes it there once: ray_sphere.h for
// shell_geometry.glsl); the test that ties the shaders to the CPU reads
// the same files in float (tests/data_formats/kernel_precision_test.cpp).
// GLSL reads them after kernel_language.glsl, which makes Real float.
#pragma once

#include <algorithm>
#include <cmath>
#include <concepts>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

// Kernel functions are defined in headers, included by many translation
// units: inline in C++, nothing in GLSL.
#define SKYBAKE_KERNEL inline
// pi, as data_formats/angles.h's kPi; GLSL has no constant of its own.
#define SKYBAKE_PI 3.14159265358979323846

namespace skybake::kernel {
using Real = double;
using Real2 = glm::dvec2;
using Real3 = glm::dvec3;
#include "data_formats/kernel/kernel_builtins.inc"
}  // namespace skybake::kernel
