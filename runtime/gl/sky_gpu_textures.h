// The textures a loaded bake becomes on a GPU, without a graphics API:
// each table's texel size, format and bytes as the GLSL library
// (runtime/glsl/) reads them. SkyGlResources uploads them to OpenGL; the web
// export (skybake export --format web) writes them for WebGL2. 2D tables
// are 2D textures (u across, r down); 4D tables 3D textures of their atlas
// (x = nu * mu_s_size + mu_s, y = mu, z = r), the single-scattering ones
// from sun texel singleScatteringFirstSunTexel on (the suns a lookup reads
// them at; mu_s_size the texels uploaded); lanes are the bake's channels
// in its channel order. The 4D tables are half floats with a power of two
// per (r, mu_s) slice by default, or RGBA32F on request
// (runtime/tables/gpu_tables.h); the 2D tables and the slice scales are
// RGBA32F; a colour bake's optical-depth texture holds its wavelength
// groups' tables below its X, Y, Z one.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "runtime/sky.h"
#include "runtime/tables/gpu_tables.h"

namespace skybake::gl {

// The tables' sampler names in the GLSL, in texture-unit order from the
// first unit a program binds them to.
inline constexpr std::array<const char*, 7> kSkySamplerNames = {
    "skybake_optical_depth",    "skybake_single_rayleigh", "skybake_single_mie",  "skybake_multiple_scattering",
    "skybake_multiple_density", "skybake_irradiance",      "skybake_slice_scales"};
// The uniform block's name in the GLSL (SkyUniformBlock's values).
inline constexpr const char* kSkyUniformBlockName = "SkybakeAtmosphere";

enum class GpuTexelFormat {
  Rgba32f,  // 4 floats
  Rgb16f,   // 3 halves (4D tables of at most 3 channels)
  Rgba16f,  // 4 halves
};

// Bytes of one texel of `format`.
int gpuTexelBytes(GpuTexelFormat format);

struct GpuTexture {
  const char* sampler = nullptr;  // its name in the GLSL (kSkySamplerNames)
  int dimensions = 2;             // 2 or 3
  int width = 1, height = 1, depth = 1;
  GpuTexelFormat format = GpuTexelFormat::Rgba32f;
  // The texels, x fastest, then y, then z: `owned`, or where they upload as
  // the loaded Sky holds them (a float upload's 4D tables) `borrowed`.
  std::vector<std::byte> owned;
  std::span<const std::byte> borrowed;
  std::span<const std::byte> bytes() const { return owned.empty() ? borrowed : std::span<const std::byte>(owned); }
};

// Every texture of kSkySamplerNames, in that order (a part the bake left
// out is one texel of zeros). The textures may point into `sky`, which
// must outlive them.
std::vector<GpuTexture> skyGpuTextures(const Sky& sky, GpuTablePrecision precision);

}  // namespace skybake::gl
