#include "baker/render/gl_sky_image.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "baker/render/sky_pixels_glsl.h"
#include "data_formats/error.h"
#include "runtime/gl/gl_program.h"
#include "runtime/gl/sky_gl_parameters.h"
#include "runtime/gl/sky_gl_resources.h"

namespace skybake {
namespace {

// Rows rendered per draw: keeps the framebuffer small (a 16k-wide strip is
// 64 MiB) and each draw short.
constexpr int kStripRows = 256;

GLint at(GLuint program, const char* name) { return glGetUniformLocation(program, name); }

// The moon, and for a camera in the atmosphere its skylight share, drawn
// into the framebuffer's first pixel by the program's skylight pass.
void setEclipseUniforms(GLuint p, const Sky& sky, const SkyView& v, const glm::dvec3& camera, bool complete) {
  const glm::dvec3& centre = v.moon.centre_m;
  glUniform4f(at(p, "moon"), static_cast<float>(centre.x), static_cast<float>(centre.y), static_cast<float>(centre.z),
              static_cast<float>(v.moon.radius_m));
  const bool inside = glm::length(camera) <= sky.atmosphere().top_radius_m;
  glUniform1i(at(p, "camera_inside"), inside ? 1 : 0);
  glm::vec4 skylight(1.0f);
  if (inside && complete) {
    glViewport(0, 0, 1, 1);
    glUniform1i(at(p, "skylight_pass"), 1);
    gl::drawFullScreenTriangle();
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, &skylight[0]);
  }
  glUniform1i(at(p, "skylight_pass"), 0);
  glUniform4f(at(p, "camera_skylight"), skylight.x, skylight.y, skylight.z, skylight.w);
}

}  // namespace

GlSkyImageRenderer::GlSkyImageRenderer() : context_(std::make_unique<gl::HeadlessGlContext>()) {}

SpectralImage GlSkyImageRenderer::render(const Sky& sky, const SkyView& v) const {
  const gl::SkyGlResources resources(sky);
  const bool eclipse = v.moon.present();
  const glm::dvec3 sun = sunDirection(v);
  const glm::dvec3 camera = cameraPosition(sky, v);
  // What the program compiles for this bake and view (sky_pixels.glsl, the
  // library's SKYBAKE_BAKE_HAS_GROUND_VIEWS, SKYBAKE_DAYLIGHT_LOOKUPS_ONLY and
  // the lookups it leaves out): only the paths it can take.
  const bool daylight = !eclipse && gl::daylightLookupsSuffice(sky, camera, sun);
  const std::string defines =
      std::string(eclipse ? "#define SKYBAKE_RENDER_ECLIPSE 1\n" : "") +
      (sky.outputs().ground_irradiance ? "" : "#define SKYBAKE_RENDER_SKY_ONLY 1\n") +
      (sky.sampler().domain().scattering_ground_views ? "#define SKYBAKE_BAKE_HAS_GROUND_VIEWS 1\n" : "") +
      (daylight ? "#define SKYBAKE_DAYLIGHT_LOOKUPS_ONLY 1\n" : "") + "#define SKYBAKE_NO_RADIANCE_TO_POINT 1\n" +
      (eclipse ? "" : "#define SKYBAKE_NO_ECLIPSE_LOOKUPS 1\n");
  const gl::GlProgram program(gl::kFullScreenVertexShader,
                              "#version 330 core\n" + defines + gl::skyGlslLibrary() + std::string(skyPixelsGlsl()));
  const GLuint p = program.id();
  glUseProgram(p);

  const PerspectiveFrame frame = perspectiveFrame(v);
  const glm::dvec3& forward = frame.forward;
  const glm::dvec3& right = frame.right;
  const glm::dvec3& up = frame.up;

  glUniform2f(at(p, "image_size"), static_cast<float>(v.width), static_cast<float>(v.height));
  glUniform1i(at(p, "projection"), v.projection == Projection::Fisheye   ? 0
                                   : v.projection == Projection::LatLong ? 1
                                                                         : 2);
  glUniform1f(at(p, "fov_rad"), static_cast<float>(radiansFromDegrees(v.fov_deg)));
  glUniform1f(at(p, "sun_azimuth_rad"), static_cast<float>(radiansFromDegrees(v.sun_azimuth_deg)));
  glUniform3f(at(p, "forward"), static_cast<float>(forward.x), static_cast<float>(forward.y),
              static_cast<float>(forward.z));
  glUniform3f(at(p, "right"), static_cast<float>(right.x), static_cast<float>(right.y), static_cast<float>(right.z));
  glUniform3f(at(p, "up"), static_cast<float>(up.x), static_cast<float>(up.y), static_cast<float>(up.z));
  glUniform2f(at(p, "half_size"), static_cast<float>(frame.half_width), static_cast<float>(frame.half_height));
  glUniform3f(at(p, "camera_m"), static_cast<float>(camera.x), static_cast<float>(camera.y),
              static_cast<float>(camera.z));
  glUniform3f(at(p, "sun_dir"), static_cast<float>(sun.x), static_cast<float>(sun.y), static_cast<float>(sun.z));

  const int strip_rows = std::min(v.height, kStripRows);
  GLuint colour = 0, framebuffer = 0;
  glGenTextures(1, &colour);
  glBindTexture(GL_TEXTURE_2D, colour);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, v.width, strip_rows, 0, GL_RGBA, GL_FLOAT, nullptr);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  // Last: creating the colour texture above rebinds the active unit.
  resources.bind(p);
  if (eclipse) setEclipseUniforms(p, sky, v, camera, complete);

  SpectralImage image{v.width, v.height, sky.channelCount(), {}};
  image.radiance.assign(static_cast<size_t>(v.width) * v.height * image.channels, 0.0f);
  std::vector<float> strip(static_cast<size_t>(v.width) * strip_rows * 4);
  for (int top = 0; complete && top < v.height; top += strip_rows) {
    const int rows = std::min(strip_rows, v.height - top);
    glViewport(0, 0, v.width, rows);
    glUniform1f(at(p, "strip_rows"), static_cast<float>(rows));
    glUniform1f(at(p, "strip_top_row"), static_cast<float>(top));
    gl::drawFullScreenTriangle();
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, v.width, rows, GL_RGBA, GL_FLOAT, strip.data());
    for (int y = 0; y < rows; ++y) {
      const float* from = &strip[static_cast<size_t>(rows - 1 - y) * v.width * 4];  // GL rows run bottom up
      for (int x = 0; x < v.width; ++x) {
        float* to = image.pixel(x, top + y);
        for (int c = 0; c < image.channels; ++c) to[c] = from[x * 4 + c];
      }
    }
  }
  const GLenum error = glGetError();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &colour);
  if (!complete) throw Error(ErrorKind::Internal, "OpenGL: the RGBA32F framebuffer is not complete");
  if (error != GL_NO_ERROR) throw Error(ErrorKind::Internal, "OpenGL: rendering the sky failed");
  return image;
}

}  // namespace skybake
