// What the GLSL library (runtime/glsl/) needs from C++: its source, the
// defines that carry the C++ lookups' constants into it, and the uniform
// block of one bake's constants (runtime/glsl/skybake_uniform_block.inc
// describes it once, for this struct and for the GLSL). No GL calls here.
#pragma once

#include <cstdint>
#include <string>

#include "runtime/sky.h"

namespace skybake::gl {

// Density layers per profile the uniform block holds; a bake with more is
// refused (Error(BadInput)) by skyUniformBlock.
inline constexpr int kMaxGlDensityLayers = 8;
// Passes of the single-scattering integral the uniform block holds: a
// colour bake's wavelength groups, as many as the C++ integral takes.
inline constexpr int kMaxGlIntegralPasses = static_cast<int>(kMaxWavelengthGroups);

// The uniform block SkybakeAtmosphere in std140 layout, its members those
// of runtime/glsl/skybake_uniform_block.inc (the one description, with each
// one's meaning and units; the GLSL block is written from it).
struct SkyUniformBlock {
  using vec4 = float[4];
  using ivec4 = std::int32_t[4];
#define SKYBAKE_MAX_DENSITY_LAYERS kMaxGlDensityLayers
#define SKYBAKE_MAX_INTEGRAL_PASSES kMaxGlIntegralPasses
#define SKYBAKE_BLOCK_MEMBER(type, name) type name;
#define SKYBAKE_BLOCK_ARRAY(type, name, count) type name[count];
#include "runtime/glsl/skybake_uniform_block.inc"
#undef SKYBAKE_BLOCK_ARRAY
#undef SKYBAKE_BLOCK_MEMBER
#undef SKYBAKE_MAX_INTEGRAL_PASSES
#undef SKYBAKE_MAX_DENSITY_LAYERS
};
static_assert(sizeof(SkyUniformBlock) == (27 + 6 * kMaxGlDensityLayers + 8 * kMaxGlIntegralPasses) * 16,
              "std140: vec4s only, no padding");

// The block's values for a loaded bake.
SkyUniformBlock skyUniformBlock(const Sky& sky);

// "#define SKYBAKE_... value" lines for every constant the library shares
// with the C++ lookups (Gauss-Legendre nodes, blend ratios, blend bands,
// segment lengths, sub-interval counts, phase normalisations, the layer limit,
// the eclipse lookups' quadrature counts and kernel constants).
std::string skyGlslDefines();

// The library's GLSL as concatenated from runtime/glsl/ (without the defines).
std::string_view skyGlslLibrarySource();

// skyGlslDefines() then the library: what a shader puts after its #version
// line (and ES precision statements) and before its own code.
std::string skyGlslLibrary();

// Whether a program that looks up the sky from `camera_m` with the sun
// along unit `sun_dir` may define SKYBAKE_DAYLIGHT_LOOKUPS_ONLY (and leave
// out the integral along the ray and the 4D tables' geometric blends): the
// camera in the atmosphere, so that every ray starts there; the sun above
// its horizon (mu_s >= 0: the blends' choice); single scattering taken from
// the tables alone at that sun (Sky::integratedSingleScatteringWeightAt 0,
// after the sun is clamped to the baked ones); a bake whose tables hold
// rays to the ground (see the .cpp). runtime/glsl/README.md; the
// browser viewer decides the same in baker/view/page/viewer.js.
bool daylightLookupsSuffice(const Sky& sky, const glm::dvec3& camera_m, const glm::dvec3& sun_dir);

}  // namespace skybake::gl
