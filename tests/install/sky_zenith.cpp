// An external program built against the installed skybake package: prints
// the zenith sky radiance for a camera at ALTITUDE_M under a sun at
// SUN_ZENITH_DEG (azimuth 0), as `skybake lookup radiance` prints it: the
// channels in the bake's order, 9 significant digits, comma-separated.
// Built by tests/install/install_test.sh with find_package(skybake) and with
// pkg-config; both must print what the installed skybake command prints.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <skybake/data_formats/angles.h>
#include <skybake/data_formats/error.h>
#include <skybake/runtime/sky.h>
#include <skybake/runtime/version.h>

int main(int argc, char** argv) {
  if (argc != 4) return std::fprintf(stderr, "usage: %s BAKE.exr ALTITUDE_M SUN_ZENITH_DEG\n", argv[0]), 2;
  try {
    const skybake::Sky sky = skybake::Sky::load(argv[1]);
    const double altitude_m = std::strtod(argv[2], nullptr);
    const double sun_zenith = skybake::radiansFromDegrees(std::strtod(argv[3], nullptr));
    const glm::dvec3 camera(0.0, 0.0, sky.atmosphere().bottom_radius_m + altitude_m);
    const glm::dvec3 sun(std::sin(sun_zenith), 0.0, std::cos(sun_zenith));
    const skybake::Spectrum zenith = sky.skyRadiance(camera, {0.0, 0.0, 1.0}, sun).radiance;
    for (int c = 0; c < sky.channelCount(); ++c) std::printf("%s%.9g", c ? "," : "", zenith[c]);
    std::printf("\n");
    std::fprintf(stderr, "runtime library %s\n", skybake::runtimeLibraryVersion());
  } catch (const skybake::Error& e) {
    return std::fprintf(stderr, "%s\n", e.what()), 2;
  }
}
