// Sky images rendered with the GLSL library on OpenGL (skybake render
// --backend gl): the projections and pixel contents of sky_image.h, one
// fragment-shader invocation per pixel into an RGBA32F framebuffer.
#pragma once

#include <memory>
#include <vector>

#include "baker/render/sky_image.h"
#include "runtime/gl/headless_gl_context.h"

namespace skybake {

class GlSkyImageRenderer {
 public:
  // Makes a headless OpenGL context; throws Error(BadInput) saying why when
  // none can be made.
  GlSkyImageRenderer();

  // As renderSkyRadiance: spectral radiance per pixel centre, without the
  // sun disk (sun_disk_pixels.h adds it).
  SpectralImage render(const Sky& sky, const SkyView& view) const;

  const gl::HeadlessGlContext& context() const { return *context_; }

 private:
  std::unique_ptr<gl::HeadlessGlContext> context_;
};

}  // namespace skybake
