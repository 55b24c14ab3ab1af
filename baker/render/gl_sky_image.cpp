#include "baker/render/gl_sky_image.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "data_formats/error.h"
#include "runtime/gl/gl_program.h"
#include "runtime/gl/sky_gl_resources.h"

namespace skybake {
namespace {

// Rows rendered per draw: keeps the framebuffer small (a 16k-wide strip is
// 64 MiB) and each draw short.
constexpr int kStripRows = 256;

// directionAtImagePoint and radianceAlong of sky_image.cpp, per pixel
// centre: every channel of the bake (lanes past its channel count are 0).
// The sun disk is added afterwards on the CPU (sun_disk_pixels.h), the same
// for both backends. Under an eclipse (SKYBAKE_RENDER_ECLIPSE defined: the
// eclipse lookups compile only for the images that need them) a first
// one-pixel draw (skylight_pass) gives the camera's skylight share, the
// same for every ray from a camera in the atmosphere, and the image's
// draws use it, as the CPU backend computes it once per image.
const char* const kFragmentMain = R"(
uniform vec2 image_size;          // pixels
uniform float strip_top_row;      // the first image row (from the top) of this draw
uniform float strip_rows;         // rows in this draw
uniform int projection;           // 0 fisheye, 1 latlong, 2 perspective
uniform float fov_rad;            // fisheye: full cone; perspective: unused (half sizes below)
uniform float sun_azimuth_rad;
uniform vec3 forward, right, up;  // perspective camera frame
uniform vec2 half_size;           // perspective: tan(fov / 2) across, times height / width down
uniform vec3 camera_m;
uniform vec3 sun_dir;
uniform int ground_lit;           // 1: the lit ground is added (the bake has ground irradiance)
#ifdef SKYBAKE_RENDER_ECLIPSE
uniform vec4 moon;                // centre (m from the planet's centre), radius (m)
uniform int skylight_pass;        // 1: this draw writes the camera's skylight share
uniform int camera_inside;        // 1: every ray starts at the camera, camera_skylight is its share
uniform vec4 camera_skylight;
#endif
layout(location = 0) out vec4 pixel;

vec3 fromZenithAzimuth(float zenith, float azimuth) {
  return vec3(sin(zenith) * cos(azimuth), sin(zenith) * sin(azimuth), cos(zenith));
}

bool pixelDirection(vec2 centre, out vec3 dir) {
  float u = centre.x / image_size.x;
  float w = centre.y / image_size.y;
  dir = vec3(0.0, 0.0, 1.0);
  if (projection == 1) {
    dir = fromZenithAzimuth(w * SKYBAKE_PI, sun_azimuth_rad + (u - 0.5) * 2.0 * SKYBAKE_PI);
    return true;
  }
  if (projection == 0) {
    float scale = min(image_size.x, image_size.y);
    float px = (2.0 * centre.x - image_size.x) / scale;
    float py = (image_size.y - 2.0 * centre.y) / scale;
    float rho = sqrt(px * px + py * py);
    if (rho > 1.0) return false;
    dir = fromZenithAzimuth(rho * fov_rad * 0.5, sun_azimuth_rad + atan(px, py));
    return true;
  }
  dir = normalize(forward + right * ((2.0 * u - 1.0) * half_size.x) + up * ((1.0 - 2.0 * w) * half_size.y));
  return true;
}

void main() {
#ifdef SKYBAKE_RENDER_ECLIPSE
  SkybakeMoon eclipse_moon = SkybakeMoon(moon.xyz, moon.w);
  if (skylight_pass != 0) {
    pixel = skybakeEclipseSkylight(camera_m, sun_dir, eclipse_moon);
    return;
  }
#endif
  // Pixel centre in image coordinates, rows from the top.
  vec2 centre = vec2(gl_FragCoord.x, strip_top_row + (strip_rows - gl_FragCoord.y));
  vec3 dir;
  if (!pixelDirection(centre, dir)) {
    pixel = vec4(0.0);
    return;
  }
#ifdef SKYBAKE_RENDER_ECLIPSE
  SkybakeRadianceAndTransmittance received;
  if (camera_inside != 0) {
    received = ground_lit != 0 ? skybakeReceivedRadiance(camera_m, dir, sun_dir, eclipse_moon, camera_skylight)
                               : skybakeSkyRadiance(camera_m, dir, sun_dir, eclipse_moon, camera_skylight);
  } else {
    received = ground_lit != 0 ? skybakeReceivedRadiance(camera_m, dir, sun_dir, eclipse_moon)
                               : skybakeSkyRadiance(camera_m, dir, sun_dir, eclipse_moon);
  }
#else
  SkybakeRadianceAndTransmittance received =
      ground_lit != 0 ? skybakeReceivedRadiance(camera_m, dir, sun_dir) : skybakeSkyRadiance(camera_m, dir, sun_dir);
#endif
  pixel = received.radiance;
}
)";

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
  const gl::GlProgram program(gl::kFullScreenVertexShader, std::string("#version 330 core\n") +
                                                               (eclipse ? "#define SKYBAKE_RENDER_ECLIPSE 1\n" : "") +
                                                               gl::skyGlslLibrary() + kFragmentMain);
  const GLuint p = program.id();
  glUseProgram(p);

  const glm::dvec3 sun = sunDirection(v);
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
  const glm::dvec3 camera = cameraPosition(sky, v);
  glUniform3f(at(p, "camera_m"), static_cast<float>(camera.x), static_cast<float>(camera.y),
              static_cast<float>(camera.z));
  glUniform3f(at(p, "sun_dir"), static_cast<float>(sun.x), static_cast<float>(sun.y), static_cast<float>(sun.z));
  glUniform1i(at(p, "ground_lit"), sky.outputs().ground_irradiance ? 1 : 0);

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
