// A loaded bake on the GPU: its tables as textures laid out as the file lays
// them out (2D tables as 2D textures, u across and r down; 4D tables as 3D
// textures of their atlas, x = nu * mu_s_size + mu_s, y = mu, z = r), and
// its constants in a uniform buffer (SkyUniformBlock). The 4D tables are
// half floats with a power of two per (r, mu_s) slice by default, or
// RGBA32F on request (runtime/tables/gpu_tables.h: formats and sizes); the 2D
// tables and the slice scales are RGBA32F; a colour bake's optical-depth
// texture holds its wavelength groups' tables below its X, Y, Z one. Lanes are the bake's channels in
// its channel order. Needs a current OpenGL 3.3 core context; everything is
// deleted with this object.
#pragma once

#include <array>

#include "runtime/gl/sky_gl_parameters.h"
#include "runtime/sky.h"
#include "runtime/tables/gpu_tables.h"

namespace skybake::gl {

// The tables' sampler names in the GLSL, in texture-unit order from the
// first unit bind() is given.
inline constexpr std::array<const char*, 7> kSkySamplerNames = {
    "skybake_optical_depth",    "skybake_single_rayleigh", "skybake_single_mie",  "skybake_multiple_scattering",
    "skybake_multiple_density", "skybake_irradiance",      "skybake_slice_scales"};
inline constexpr const char* kSkyUniformBlockName = "SkybakeAtmosphere";

class SkyGlResources {
 public:
  // Uploads the tables (a part the bake left out becomes one texel of 0)
  // and the constants. Throws Error(BadInput) for a bake whose tables exceed
  // the context's texture limits or whose profiles have too many layers.
  explicit SkyGlResources(const Sky& sky, GpuTablePrecision precision = GpuTablePrecision::Half);
  ~SkyGlResources();
  SkyGlResources(const SkyGlResources&) = delete;
  SkyGlResources& operator=(const SkyGlResources&) = delete;

  // Makes `program` current and binds the tables to texture units
  // first_unit .. first_unit + 6 and the constants to uniform-buffer
  // binding point `block_binding`.
  void bind(unsigned program, int first_unit = 0, unsigned block_binding = 0) const;

  const SkyUniformBlock& constants() const { return constants_; }

 private:
  SkyUniformBlock constants_;
  std::array<unsigned, kSkySamplerNames.size()> textures_{};  // in kSkySamplerNames' order
  std::array<unsigned, kSkySamplerNames.size()> targets_{};   // GL_TEXTURE_2D or GL_TEXTURE_3D
  unsigned uniform_buffer_ = 0;
};

}  // namespace skybake::gl
