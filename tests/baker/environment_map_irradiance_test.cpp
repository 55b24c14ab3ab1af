// A lat-long environment map of the default Earth, integrated over the
// upper hemisphere as a renderer integrates it (radiance times cos(zenith)
// times solid angle, per pixel), gives the irradiance on a horizontal
// surface that Sky::irradiance gives (sun plus sky, what `skybake lookup
// irradiance` prints), within 2 %, for the sun from the zenith to 85 deg.
// That needs the sun disk integrated over pixel areas (sun_disk_pixels.h):
// sampled at pixel centres, the disk (0.27 deg in radius) falls between the
// centres of this map's 0.625 deg pixels and the sun's light, 50 to 90 %
// of the total, is lost.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "baker/render/sky_image.h"
#include "baker/render/sun_disk_pixels.h"
#include "data_formats/angles.h"
#include "runtime/sky.h"

namespace skybake {
namespace {

// The map's size: 576 x 288 pixels of 0.625 deg. Rows of 0.625 deg put a
// row boundary on every multiple of 5 deg, so the sun's centre is on one
// and its disk falls half in the row above, half in the row below, which
// cancels the first-order error of taking a row's cosine for the whole row
// (at 85 deg, cos(zenith) changes by 19 % across a row). The horizon is a
// row boundary too, so no row mixes sky and ground.
constexpr int kMapWidth = 576;
constexpr int kMapHeight = 288;

// The test's bound: the map's integral against the irradiance table. What
// remains besides the sun disk: the sky's radiance sampled once per pixel
// against the irradiance table's own quadrature and interpolation (about
// 0.5 % by day, measured), and the sun's transmittance averaged over its
// disk rather than taken at its centre.
constexpr double kMaxRelativeError = 0.02;

TEST(EnvironmentMapIrradiance, MatchesSkyIrradianceFromZenithTo85Degrees) {
  const Sky sky = Sky::load(SKYBAKE_TEST_BAKE_DIR "/earth.exr");
  SkyView view;
  view.projection = Projection::LatLong;
  view.altitude_m = 0.0;
  view.width = kMapWidth;
  view.height = kMapHeight;
  const glm::dvec3 camera(0.0, 0.0, sky.atmosphere().bottom_radius_m);
  const glm::dvec3 up(0.0, 0.0, 1.0);
  const double row_height_rad = kPi / kMapHeight;
  const double column_width_rad = 2.0 * kPi / kMapWidth;
  double worst = 0.0;
  for (int sun_zenith_deg = 0; sun_zenith_deg <= 85; sun_zenith_deg += 5) {
    view.sun_zenith_deg = sun_zenith_deg;
    SpectralImage image = renderSkyRadiance(sky, view);
    addSunDisk(sky, view, image);
    std::vector<double> map(static_cast<size_t>(image.channels), 0.0);
    for (int y = 0; y < kMapHeight / 2; ++y) {
      // A row's integral of cos(zenith) over its solid angle, per pixel:
      // the exact weight of a pixel of uniform radiance.
      const double s0 = std::sin(y * row_height_rad), s1 = std::sin((y + 1) * row_height_rad);
      const double weight_sr = column_width_rad * 0.5 * (s1 * s1 - s0 * s0);
      for (int x = 0; x < kMapWidth; ++x) {
        for (int c = 0; c < image.channels; ++c) map[static_cast<size_t>(c)] += image.pixel(x, y)[c] * weight_sr;
      }
    }
    const SunAndSkyIrradiance e = sky.irradiance(camera, up, sunDirection(view));
    for (int c = 0; c < image.channels; ++c) {
      const double expected = e.sun[c] + e.sky[c];
      const double relative = map[static_cast<size_t>(c)] / expected - 1.0;
      std::printf("sun %2d deg, %.0f nm: map %.5g, lookup %.5g (sun %.5g, sky %.5g) W m^-2 nm^-1: %+.3f %%\n",
                  sun_zenith_deg, sky.atmosphere().wavelengths_nm[static_cast<size_t>(c)], map[static_cast<size_t>(c)],
                  expected, static_cast<double>(e.sun[c]), static_cast<double>(e.sky[c]), 100.0 * relative);
      EXPECT_LT(std::abs(relative), kMaxRelativeError) << "sun zenith " << sun_zenith_deg << " deg, channel " << c;
      worst = std::max(worst, std::abs(relative));
    }
  }
  std::printf("worst: %.3f %%\n", 100.0 * worst);
}

}  // namespace
}  // namespace skybake
