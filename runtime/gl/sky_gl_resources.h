// A loaded bake on the GPU: its tables as the textures of
// sky_gpu_textures.h (their layout and formats), and its constants in a
// uniform buffer (SkyUniformBlock). Needs a current OpenGL 3.3 core
// context; everything is deleted with this object.
#pragma once

#include <array>

#include "runtime/gl/sky_gl_parameters.h"
#include "runtime/gl/sky_gpu_textures.h"
#include "runtime/sky.h"
#include "runtime/tables/gpu_tables.h"

namespace skybake::gl {

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
