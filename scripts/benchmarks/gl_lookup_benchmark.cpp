// Sky-radiance rays per second of the GLSL library on OpenGL: one full-screen
// pass at 1920x1080, each pixel a skybakeSkyRadiance call for one view
// direction (uniform over the sphere, an equirectangular map) from a camera
// 1 km up, finished with glFinish; the sun 30 deg from the zenith (day) and
// 95 deg (twilight: single scattering integrated along each ray). The
// CPU's figure to compare is bench_lookup's BM_SkyRadianceBatch (one core).
// On a machine without a GPU the context is Mesa's llvmpipe, on all cores.
// The bake comes from $SKYBAKE_BAKE (default out/earth.exr).
#include <epoxy/gl.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <memory>

#include "runtime/gl/gl_program.h"
#include "runtime/gl/headless_gl_context.h"
#include "runtime/gl/sky_gl_resources.h"

namespace {

constexpr int kWidth = 1920;
constexpr int kHeight = 1080;

const char* const kFragmentMain = R"(
uniform vec3 camera_m;
uniform vec3 sun_dir;
layout(location = 0) out vec4 pixel;
void main() {
  vec2 uv = gl_FragCoord.xy / vec2(1920.0, 1080.0);
  float zenith = uv.y * SKYBAKE_PI;
  float azimuth = uv.x * 2.0 * SKYBAKE_PI;
  vec3 dir = vec3(sin(zenith) * cos(azimuth), sin(zenith) * sin(azimuth), cos(zenith));
  pixel = skybakeSkyRadiance(camera_m, dir, sun_dir).radiance;
}
)";

void BM_GlSkyRadiancePass(benchmark::State& state) {
  static skybake::gl::HeadlessGlContext context;
  static const skybake::Sky sky = [] {
    const char* path = std::getenv("SKYBAKE_BAKE");
    return skybake::Sky::load(path != nullptr ? path : "out/earth.exr");
  }();
  static const skybake::gl::SkyGlResources resources(sky);
  static const skybake::gl::GlProgram program(skybake::gl::kFullScreenVertexShader,
                                              "#version 330 core\n" + skybake::gl::skyGlslLibrary() + kFragmentMain);
  GLuint colour = 0, framebuffer = 0;
  glGenTextures(1, &colour);
  glBindTexture(GL_TEXTURE_2D, colour);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kWidth, kHeight, 0, GL_RGBA, GL_FLOAT, nullptr);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
  resources.bind(program.id());
  const double zenith = skybake::radiansFromDegrees(static_cast<double>(state.range(0)));
  glUniform3f(glGetUniformLocation(program.id(), "camera_m"), 0.0f, 0.0f,
              static_cast<float>(sky.atmosphere().bottom_radius_m + 1000.0));
  glUniform3f(glGetUniformLocation(program.id(), "sun_dir"), static_cast<float>(std::sin(zenith)), 0.0f,
              static_cast<float>(std::cos(zenith)));
  // One pixel first: llvmpipe compiles the shader at its first draw.
  glViewport(0, 0, 1, 1);
  skybake::gl::drawFullScreenTriangle();
  glFinish();
  glViewport(0, 0, kWidth, kHeight);
  for (auto _ : state) {
    skybake::gl::drawFullScreenTriangle();
    glFinish();
  }
  state.SetItemsProcessed(state.iterations() * kWidth * kHeight);
  state.SetLabel(context.description());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &colour);
}
BENCHMARK(BM_GlSkyRadiancePass)
    ->ArgName("sun_zenith_deg")
    ->Arg(30)
    ->Arg(95)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(5.0);

}  // namespace

BENCHMARK_MAIN();
