// An offscreen OpenGL 3.3 core context without a window or display server:
// EGL on Mesa's surfaceless platform, else the first EGL device
// (EGL_EXT_platform_device), else the default display with a 1x1 pbuffer.
// Mesa's llvmpipe renders it on the CPU where there is no GPU.
#pragma once

#include <string>

namespace skybake::gl {

class HeadlessGlContext {
 public:
  // Creates the context and makes it current on this thread. Throws
  // Error(BadInput) saying what failed when none can be made (no EGL
  // display, no OpenGL 3.3 core support).
  HeadlessGlContext();
  ~HeadlessGlContext();
  HeadlessGlContext(const HeadlessGlContext&) = delete;
  HeadlessGlContext& operator=(const HeadlessGlContext&) = delete;

  // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
  std::string description() const;

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  void* surface_ = nullptr;  // EGLSurface, only without surfaceless contexts
};

}  // namespace skybake::gl
