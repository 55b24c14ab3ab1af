#include "runtime/gl/headless_gl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstring>
#include <vector>

#include <fmt/format.h>

#include "data_formats/error.h"

namespace skybake::gl {
namespace {

bool hasExtension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const size_t length = std::strlen(name);
  for (const char* p = std::strstr(list, name); p != nullptr; p = std::strstr(p + length, name)) {
    if ((p == list || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0')) return true;
  }
  return false;
}

[[noreturn]] void refuse(const std::string& what) {
  throw Error(ErrorKind::BadInput, fmt::format("no headless OpenGL 3.3 context: {} (EGL error 0x{:x})", what,
                                               static_cast<unsigned>(eglGetError())));
}

// A display on the first platform that offers one, initialised.
EGLDisplay openDisplay() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  std::vector<EGLDisplay> candidates;
  if (hasExtension(client, "EGL_MESA_platform_surfaceless")) {
    candidates.push_back(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
  }
  if (hasExtension(client, "EGL_EXT_platform_device") && hasExtension(client, "EGL_EXT_device_enumeration")) {
    EGLDeviceEXT device = nullptr;
    EGLint count = 0;
    if (eglQueryDevicesEXT(1, &device, &count) && count > 0) {
      candidates.push_back(eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr));
    }
  }
  candidates.push_back(eglGetDisplay(EGL_DEFAULT_DISPLAY));
  for (EGLDisplay display : candidates) {
    EGLint major = 0, minor = 0;
    if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor)) return display;
  }
  refuse("no EGL display could be initialised (surfaceless, device or default)");
}

}  // namespace

HeadlessGlContext::HeadlessGlContext() {
  EGLDisplay display = openDisplay();
  display_ = display;
  if (!eglBindAPI(EGL_OPENGL_API)) {
    eglTerminate(display);
    refuse("the EGL display offers no desktop OpenGL");
  }
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint config_count = 0;
  if (!eglChooseConfig(display, config_attributes, &config, 1, &config_count) || config_count < 1) {
    eglTerminate(display);
    refuse("no EGL config renders desktop OpenGL to a pbuffer");
  }
  const EGLint context_attributes[] = {
      EGL_CONTEXT_MAJOR_VERSION,           3,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
  if (context == EGL_NO_CONTEXT) {
    eglTerminate(display);
    refuse("the EGL display cannot create an OpenGL 3.3 core context");
  }
  context_ = context;
  EGLSurface surface = EGL_NO_SURFACE;
  if (!epoxy_has_egl_extension(display, "EGL_KHR_surfaceless_context")) {
    const EGLint pbuffer_attributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    surface = eglCreatePbufferSurface(display, config, pbuffer_attributes);
    surface_ = surface;
  }
  if (!eglMakeCurrent(display, surface, surface, context)) {
    if (surface != EGL_NO_SURFACE) eglDestroySurface(display, surface);
    eglDestroyContext(display, context);
    eglTerminate(display);
    refuse("the OpenGL context cannot be made current");
  }
}

HeadlessGlContext::~HeadlessGlContext() {
  EGLDisplay display = display_;
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (surface_ != nullptr) eglDestroySurface(display, surface_);
  eglDestroyContext(display, context_);
  eglTerminate(display);
}

std::string HeadlessGlContext::description() const {
  const auto text = [](GLenum name) {
    const GLubyte* s = glGetString(name);
    return s != nullptr ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return text(GL_RENDERER) + ", " + text(GL_VERSION);
}

}  // namespace skybake::gl
