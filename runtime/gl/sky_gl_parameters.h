// What the GLSL library (runtime/glsl/) needs from C++: its source, the
// defines that carry the C++ lookups' constants into it, and the uniform
// block of one bake's constants (skybake_parameters.glsl declares the
// same block). No GL calls here.
#pragma once

#include <cstdint>
#include <string>

#include "runtime/sky.h"

namespace skybake::gl {

// Density layers per profile the uniform block holds; a bake with more is
// refused (Error(BadInput)) by skyUniformBlock.
inline constexpr int kMaxGlDensityLayers = 8;

// The uniform block SkybakeAtmosphere in std140 layout; every member a
// 16-byte vec4 or ivec4, in the order the GLSL declares them (see there
// for each one's meaning and units).
struct SkyUniformBlock {
  float radii_m[4];                // bottom, top, H (m), sun angular radius (rad)
  float scattering_domain[4];      // rho min, rho max (m), sun coordinate min, 1 / its span
  float mu_s_map[4];               // d_min (m), 1 / (d_max - d_min) (m^-1), 1 / A, defined
  float mu_s_below[4];             // below-horizon share, day coordinate at the horizon, 1 / mu_s_min, spacing c
  float sun_angles[4];             // baked mu_s min, max; Mie g; multiple-scattering g_ms
  float phase[4];                  // Cornette-Shanks normalisations for g, g_ms (sr^-1); sun disk chord^2
  int32_t scattering_size[4];      // r, mu, mu_s, nu texels
  int32_t table_2d_size[4];        // optical depth mu, r; irradiance mu_s, r texels
  int32_t parts[4];                // ground views, single Mie, multiple density, irradiance present
  int32_t outputs[4];              // radiance to points, ground irradiance, channel count, channel kind
  int32_t profile_layers[4];       // Rayleigh, Mie, absorption
  float sun_irradiance[4];         // W m^-2 nm^-1
  float solar_radiance[4];         // W m^-2 sr^-1 nm^-1
  float rayleigh_scattering[4];    // m^-1
  float mie_scattering[4];         // m^-1
  float mie_extinction[4];         // m^-1
  float absorption_extinction[4];  // m^-1
  float ground_albedo[4];
  float column_mie_share_power[4];
  float wavelengths_nm[4];
  float night[4];              // night continuation: edge mu_s, edge sine, 1 / tan(span / 2), 4D tables continue
  float night_exponent[4];     // its power per channel
  float luminance_weights[4];  // cd m^-2 per unit of each channel (Sky::luminanceWeights)
  float layer_shape[3 * kMaxGlDensityLayers][4];  // width (m), exp_term, exp_scale (m^-1), linear_term (m^-1)
  float layer_constant[3 * kMaxGlDensityLayers][4];
};
static_assert(sizeof(SkyUniformBlock) == (23 + 6 * kMaxGlDensityLayers) * 16, "std140: vec4s only, no padding");

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

}  // namespace skybake::gl
