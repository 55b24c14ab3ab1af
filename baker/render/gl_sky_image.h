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

  // As renderSkyRadiance: linear RGB radiance, W m^-2 sr^-1 nm^-1, rows top
  // to bottom, R, G, B the channels nearest 680, 550 and 440 nm.
  std::vector<float> render(const Sky& sky, const SkyView& view) const;

  const gl::HeadlessGlContext& context() const { return *context_; }

 private:
  std::unique_ptr<gl::HeadlessGlContext> context_;
};

}  // namespace skybake
