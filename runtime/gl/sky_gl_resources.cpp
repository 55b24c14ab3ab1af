#include "runtime/gl/sky_gl_resources.h"

#include <epoxy/gl.h>

#include <fmt/format.h>

#include "data_formats/error.h"
#include "runtime/gl/sky_gpu_textures.h"

namespace skybake::gl {
namespace {

void setNearest(GLenum target) {
  // texelFetch ignores filtering, but a texture whose minification filter
  // wants mipmaps it lacks is incomplete and reads as 0.
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void checkFits(const GpuTexture& t) {
  GLint max_size = 0;
  glGetIntegerv(t.dimensions == 2 ? GL_MAX_TEXTURE_SIZE : GL_MAX_3D_TEXTURE_SIZE, &max_size);
  if (t.width > max_size || t.height > max_size || t.depth > max_size) {
    throwBadInput(fmt::format("the {} table ({}x{}{}) exceeds this OpenGL's largest {} texture ({})", t.sampler,
                              t.width, t.height, t.dimensions == 2 ? "" : fmt::format("x{} as a 3D texture", t.depth),
                              t.dimensions == 2 ? "2D" : "3D", max_size));
  }
}

GLuint upload(const GpuTexture& t) {
  checkFits(t);
  const GLenum target = t.dimensions == 2 ? GL_TEXTURE_2D : GL_TEXTURE_3D;
  GLenum internal_format = GL_RGBA32F, format = GL_RGBA, type = GL_FLOAT;
  if (t.format == GpuTexelFormat::Rgb16f) internal_format = GL_RGB16F, format = GL_RGB, type = GL_HALF_FLOAT;
  if (t.format == GpuTexelFormat::Rgba16f) internal_format = GL_RGBA16F, type = GL_HALF_FLOAT;
  GLuint id = 0;
  glGenTextures(1, &id);
  glBindTexture(target, id);
  setNearest(target);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows of 6-byte texels
  if (t.dimensions == 2) {
    glTexImage2D(target, 0, internal_format, t.width, t.height, 0, format, type, t.bytes().data());
  } else {
    glTexImage3D(target, 0, internal_format, t.width, t.height, t.depth, 0, format, type, t.bytes().data());
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  return id;
}

}  // namespace

SkyGlResources::SkyGlResources(const Sky& sky, GpuTablePrecision precision) : constants_(skyUniformBlock(sky)) {
  const std::vector<GpuTexture> textures = skyGpuTextures(sky, precision);
  for (size_t i = 0; i < textures.size(); ++i) {
    textures_[i] = upload(textures[i]);
    targets_[i] = textures[i].dimensions == 2 ? GL_TEXTURE_2D : GL_TEXTURE_3D;
  }
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
