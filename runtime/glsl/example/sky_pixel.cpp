// The GLSL runtime's minimal use: a headless OpenGL context, a bake's tables
// uploaded, a fragment shader that calls the GLSL library, one pixel read
// back. Prints the zenith sky radiance 1 km up under a sun 30 deg from the
// zenith, per channel in the bake's order, in W m^-2 sr^-1 nm^-1.
#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <skybake/data_formats/error.h>
#include <skybake/runtime/gl/gl_program.h>
#include <skybake/runtime/gl/headless_gl_context.h>  // or your own window's context
#include <skybake/runtime/gl/sky_gl_parameters.h>
#include <skybake/runtime/gl/sky_gl_resources.h>
#include <skybake/runtime/sky.h>

int main(int argc, char** argv) {
  if (argc != 2) return std::fprintf(stderr, "usage: %s BAKE.exr\n", argv[0]), 2;
  try {
    const skybake::Sky sky = skybake::Sky::load(argv[1]);
    const skybake::gl::HeadlessGlContext context;   // throws skybake::Error if none can be made
    const skybake::gl::SkyGlResources tables(sky);  // textures and the uniform buffer
    const skybake::gl::GlProgram program(skybake::gl::kFullScreenVertexShader,
                                         "#version 330 core\n" + skybake::gl::skyGlslLibrary() + R"(
uniform vec3 camera_m;  // metres from the planet's centre
uniform vec3 sun_dir;   // unit vector toward the sun
out vec4 colour;
void main() {
  colour = skybakeSkyRadiance(camera_m, vec3(0.0, 0.0, 1.0), sun_dir).radiance;
}
)");
    // One float pixel to draw into (a renderer draws into its own targets;
    // make them before tables.bind, which leaves units 0 to 6 bound).
    GLuint target = 0, framebuffer = 0;
    glGenTextures(1, &target);
    glBindTexture(GL_TEXTURE_2D, target);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, nullptr);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
    glViewport(0, 0, 1, 1);

    tables.bind(program.id());  // glUseProgram, the tables on units 0 to 6, the uniform block on binding 0
    const float altitude_m = 1000.0f, sun_zenith_rad = 30.0f * 3.14159265f / 180.0f;
    glUniform3f(glGetUniformLocation(program.id(), "camera_m"), 0.0f, 0.0f,
                static_cast<float>(sky.atmosphere().bottom_radius_m) + altitude_m);
    glUniform3f(glGetUniformLocation(program.id(), "sun_dir"), std::sin(sun_zenith_rad), 0.0f,
                std::cos(sun_zenith_rad));
    skybake::gl::drawFullScreenTriangle();

    float radiance[4] = {};
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, radiance);
    for (int c = 0; c < std::min(sky.channelCount(), 4); ++c) std::printf("%s%.9g", c ? "," : "", radiance[c]);
    std::printf("\n");
  } catch (const skybake::Error& e) {
    return std::fprintf(stderr, "%s\n", e.what()), 2;
  }
}
