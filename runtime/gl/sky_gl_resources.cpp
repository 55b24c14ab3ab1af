#include "runtime/gl/sky_gl_resources.h"

#include <epoxy/gl.h>

#include <fmt/format.h>

#include "data_formats/error.h"

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

GLuint upload4D(const Texture4D& t, const char* name) {
  const bool empty = t.texels.empty();
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max_size);
  if (!empty && (t.atlasWidth() > max_size || t.mu_size > max_size || t.r_size > max_size)) {
    throwBadInput(fmt::format("the {} table ({}x{}x{} as a 3D texture) exceeds this OpenGL's largest 3D texture ({})",
                              name, t.atlasWidth(), t.mu_size, t.r_size, max_size));
  }
  GLuint id = 0;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_3D, id);
  setNearest(GL_TEXTURE_3D);
  // The atlas's memory order (x fastest, then mu, then r) is the 3D
  // texture's (x, y, z): the file's layout uploads unchanged.
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA32F, empty ? 1 : t.atlasWidth(), empty ? 1 : t.mu_size, empty ? 1 : t.r_size, 0,
               GL_RGBA, GL_FLOAT, empty ? &kZeroTexel : t.texels.data());
  return id;
}

}  // namespace

SkyGlResources::SkyGlResources(const Sky& sky) : constants_(skyUniformBlock(sky)) {
  const BakeTables& t = sky.tables();
  textures_ = {upload2D(t.optical_depth, "optical_depth"),
               upload4D(t.single_rayleigh, "single_rayleigh"),
               upload4D(t.single_mie, "single_mie"),
               upload4D(t.multiple_scattering, "multiple_scattering"),
               upload4D(t.multiple_density, "multiple_scattering_density"),
               upload2D(t.irradiance, "irradiance")};
  targets_ = {GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_3D, GL_TEXTURE_3D, GL_TEXTURE_3D, GL_TEXTURE_2D};
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
