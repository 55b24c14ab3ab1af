#include "runtime/gl/sky_gl_resources.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "data_formats/error.h"
#include "runtime/tables/gpu_tables.h"

namespace skybake::gl {
namespace {

const Spectrum kZeroTexel(0.0f);

void setNearest(GLenum target) {
  // texelFetch ignores filtering, but a texture whose minification filter
  // wants mipmaps it lacks is incomplete and reads as 0.
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

GLuint upload2D(const Texture2D& t, const char* name) {
  const bool empty = t.texels.empty();
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (!empty && (t.width > max_size || t.height > max_size)) {
    throwBadInput(fmt::format("the {} table ({}x{}) exceeds this OpenGL's largest texture ({})", name, t.width,
                              t.height, max_size));
  }
  GLuint id = 0;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_2D, id);
  setNearest(GL_TEXTURE_2D);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, empty ? 1 : t.width, empty ? 1 : t.height, 0, GL_RGBA, GL_FLOAT,
               empty ? &kZeroTexel : t.texels.data());
  return id;
}

void checkFits3D(const Texture4D& t, const char* name) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max_size);
  if (t.atlasWidth() > max_size || t.mu_size > max_size || t.r_size > max_size) {
    throwBadInput(fmt::format("the {} table ({}x{}x{} as a 3D texture) exceeds this OpenGL's largest 3D texture ({})",
                              name, t.atlasWidth(), t.mu_size, t.r_size, max_size));
  }
}

// A 4D table as a 3D texture. The atlas's memory order (x fastest, then mu,
// then r) is the 3D texture's (x, y, z): the file's layout uploads
// unchanged. Half: its slice scales go to `slice_scales`, lane `lane`.
GLuint upload4D(const Texture4D& t, const char* name, int channels, GpuTablePrecision precision,
                std::vector<Spectrum>& slice_scales, int lane) {
  const bool empty = t.texels.empty();
  if (!empty) checkFits3D(t, name);
  GLuint id = 0;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_3D, id);
  setNearest(GL_TEXTURE_3D);
  if (empty || precision == GpuTablePrecision::Float) {
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA32F, empty ? 1 : t.atlasWidth(), empty ? 1 : t.mu_size, empty ? 1 : t.r_size,
                 0, GL_RGBA, GL_FLOAT, empty ? &kZeroTexel : t.texels.data());
    return id;
  }
  const HalfTable4D half = halfTable4D(t, channels);
  for (size_t s = 0; s < half.slice_scales.size(); ++s) slice_scales[s][lane] = half.slice_scales[s];
  const bool rgb = half.components == 3;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);  // rows of 6-byte texels
  glTexImage3D(GL_TEXTURE_3D, 0, rgb ? GL_RGB16F : GL_RGBA16F, t.atlasWidth(), t.mu_size, t.r_size, 0,
               rgb ? GL_RGB : GL_RGBA, GL_HALF_FLOAT, half.values.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  return id;
}

// The optical-depth texture: the bake's table, and below it a colour
// bake's wavelength groups' tables in order (the integral's passes,
// skybake_integral_passes).
Texture2D opticalDepthRows(const Sky& sky) {
  Texture2D stacked = sky.tables().optical_depth;
  for (const Texture2D& g : sky.wavelengthOpticalDepth()) {
    if (g.width != stacked.width) throw Error(ErrorKind::Internal, "wavelength optical depths of another width");
    stacked.texels.insert(stacked.texels.end(), g.texels.begin(), g.texels.end());
    stacked.height += g.height;
  }
  return stacked;
}

}  // namespace

SkyGlResources::SkyGlResources(const Sky& sky, GpuTablePrecision precision) : constants_(skyUniformBlock(sky)) {
  const BakeTables& t = sky.tables();
  const int channels = sky.channelCount();
  // Lanes x, y, z, w: single Rayleigh, single Mie, multiple scattering, its
  // density (skybake_parameters.glsl); 1 where a table is float or absent.
  const Texture4D& shape = t.single_rayleigh;
  Texture2D slice_scales(std::max(shape.mu_s_size, 1), std::max(shape.r_size, 1));
  for (Spectrum& scale : slice_scales.texels) scale = Spectrum(1.0f);
  textures_ = {upload2D(opticalDepthRows(sky), "optical_depth"),
               upload4D(t.single_rayleigh, "single_rayleigh", channels, precision, slice_scales.texels, 0),
               upload4D(t.single_mie, "single_mie", channels, precision, slice_scales.texels, 1),
               upload4D(t.multiple_scattering, "multiple_scattering", channels, precision, slice_scales.texels, 2),
               upload4D(t.multiple_density, "multiple_scattering_density", channels, precision, slice_scales.texels, 3),
               upload2D(t.irradiance, "irradiance"),
               upload2D(slice_scales, "slice scales")};
  targets_ = {GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_3D, GL_TEXTURE_3D, GL_TEXTURE_3D, GL_TEXTURE_2D, GL_TEXTURE_2D};
  glGenBuffers(1, &uniform_buffer_);
  glBindBuffer(GL_UNIFORM_BUFFER, uniform_buffer_);
  glBufferData(GL_UNIFORM_BUFFER, sizeof(constants_), &constants_, GL_STATIC_DRAW);
  glBindBuffer(GL_UNIFORM_BUFFER, 0);
  if (glGetError() != GL_NO_ERROR) throw Error(ErrorKind::Internal, "uploading the bake's tables to OpenGL failed");
}

SkyGlResources::~SkyGlResources() {
  glDeleteTextures(static_cast<GLsizei>(textures_.size()), textures_.data());
  glDeleteBuffers(1, &uniform_buffer_);
}

void SkyGlResources::bind(unsigned program, int first_unit, unsigned block_binding) const {
  glUseProgram(program);
  const GLuint block = glGetUniformBlockIndex(program, kSkyUniformBlockName);
  if (block != GL_INVALID_INDEX) glUniformBlockBinding(program, block, block_binding);
  glBindBufferBase(GL_UNIFORM_BUFFER, block_binding, uniform_buffer_);
  for (size_t i = 0; i < textures_.size(); ++i) {
    const GLint unit = first_unit + static_cast<GLint>(i);
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(targets_[i], textures_[i]);
    const GLint location = glGetUniformLocation(program, kSkySamplerNames[i]);
    if (location >= 0) glUniform1i(location, unit);  // -1: the shader does not use this table
  }
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace skybake::gl
