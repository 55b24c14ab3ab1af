// Prints the GLSL library wrapped in a minimal fragment shader that calls
// every public function, for one target: "330" (OpenGL 3.3 core), "300es"
// (OpenGL ES 3.00) or "450" (Vulkan: explicit bindings), so that
// glslangValidator and spirv-cross can check it (glsl_spirv_test.sh).
#include <cstdio>
#include <string>

#include "runtime/gl/sky_gl_parameters.h"

namespace {

const char* const kMain = R"(
out vec4 skybake_check_colour;
uniform vec3 skybake_check_camera_m;
uniform vec3 skybake_check_sun_dir;
void main() {
  vec3 dir = normalize(vec3(gl_FragCoord.xy - 64.0, 10.0));
  vec3 camera = skybake_check_camera_m;
  vec3 sun = skybake_check_sun_dir;
  SkybakeRadianceAndTransmittance sky = skybakeSkyRadiance(camera, dir, sun, 100.0);
  SkybakeRadianceAndTransmittance received = skybakeReceivedRadiance(camera, dir, sun);
  SkybakeRadianceAndTransmittance aerial = skybakeRadianceToPoint(camera, camera + dir * 5000.0, sun, 0.0);
  SkybakeSunAndSkyIrradiance irradiance = skybakeSunAndSkyIrradiance(camera, dir, sun);
  vec4 solar = skybakeInSunDisk(dir, sun) ? skybakeSolarRadiance() * sky.transmittance : vec4(0.0);
  // A solar eclipse: the moon 0.1 deg from the sun, seen from the camera.
  SkybakeMoon moon = SkybakeMoon(camera + normalize(sun + vec3(1.7e-3, 0.0, 0.0)) * 3.844e8, 1.8e6);
  vec4 skylight = skybakeEclipseSkylight(camera, sun, moon);
  SkybakeRadianceAndTransmittance eclipsed = skybakeSkyRadiance(camera, dir, sun, moon, skylight);
  SkybakeRadianceAndTransmittance eclipsed_received = skybakeReceivedRadiance(camera, dir, sun, moon);
  SkybakeSunAndSkyIrradiance eclipsed_irradiance = skybakeSunAndSkyIrradiance(camera, dir, sun, moon);
  SkybakeRadianceAndTransmittance eclipsed_aerial = skybakeRadianceToPoint(camera, camera + dir * 5000.0, sun, moon);
  SkybakeRadianceAndTransmittance eclipsed_aerial_given =
      skybakeRadianceAlongRayTo(camera, dir, 5000.0, sun, moon, skylight);
  float past_moon = skybakeMoonVisibleSunFraction(moon, camera, sun, 4.65e-3);
  vec4 eclipsed_solar = skybakeInSunDiskPastMoon(camera, dir, sun, moon) ? skybakeSolarRadiance() : vec4(0.0);
  skybake_check_colour = sky.radiance + received.radiance + aerial.radiance + aerial.transmittance +
                         irradiance.sun + irradiance.sky + solar + skybakeTransmittance(camera, camera + dir) +
                         eclipsed.radiance + skybakeSkyRadiance(camera, dir, sun, moon).radiance +
                         eclipsed_received.radiance + eclipsed_irradiance.sun + eclipsed_irradiance.sky +
                         eclipsed_solar * past_moon + eclipsed_aerial.radiance + eclipsed_aerial_given.radiance;
}
)";

}  // namespace

int main(int argc, char** argv) {
  const std::string target = argc > 1 ? argv[1] : "";
  std::string header;
  if (target == "330") {
    header = "#version 330 core\n";
  } else if (target == "300es") {
    header =
        "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
        "precision highp sampler3D;\n";
  } else if (target == "450") {
    header =
        "#version 450\n#define SKYBAKE_UNIFORM_BLOCK_LAYOUT layout(std140, set = 0, binding = 0)\n"
        "#define SKYBAKE_SAMPLER_LAYOUT(unit) layout(set = 0, binding = unit)\n";
  } else {
    std::fprintf(stderr, "usage: %s 330|300es|450\n", argv[0]);
    return 2;
  }
  std::string main_part = kMain;
  if (target == "450") {
    // Vulkan has no loose uniforms: the check's own inputs go in a block.
    main_part.replace(main_part.find("uniform vec3 skybake_check_camera_m;\nuniform vec3 skybake_check_sun_dir;"),
                      std::string("uniform vec3 skybake_check_camera_m;\nuniform vec3 skybake_check_sun_dir;").size(),
                      "layout(std140, set = 0, binding = 7) uniform Check {\n  vec3 skybake_check_camera_m;\n"
                      "  vec3 skybake_check_sun_dir;\n};");
    main_part.replace(main_part.find("out vec4"), 8, "layout(location = 0) out vec4");
  }
  std::fputs((header + skybake::gl::skyGlslLibrary() + main_part).c_str(), stdout);
  return 0;
}
