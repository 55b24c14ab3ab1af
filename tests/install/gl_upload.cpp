// An external program built against the installed skybake::gl: makes a
// headless OpenGL context, uploads BAKE's tables and prints what it made.
// Built by tests/install/install_test.sh where the package has skybake::gl.
#include <cstdio>

#include <skybake/data_formats/error.h>
#include <skybake/runtime/gl/headless_gl_context.h>
#include <skybake/runtime/gl/sky_gl_parameters.h>
#include <skybake/runtime/gl/sky_gl_resources.h>
#include <skybake/runtime/sky.h>

int main(int argc, char** argv) {
  if (argc != 2) return std::fprintf(stderr, "usage: %s BAKE.exr\n", argv[0]), 2;
  try {
    const skybake::Sky sky = skybake::Sky::load(argv[1]);
    const skybake::gl::HeadlessGlContext context;
    const skybake::gl::SkyGlResources tables(sky);
    std::printf("gl upload: %zu characters of GLSL, tables on %s\n", skybake::gl::skyGlslLibrary().size(),
                context.description().c_str());
  } catch (const skybake::Error& e) {
    return std::fprintf(stderr, "%s\n", e.what()), 2;
  }
}
