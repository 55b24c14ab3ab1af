// The sun disk integrated over pixel areas (sun_disk_pixels.h) in every
// projection: the image's integral of the disk's radiance over solid angle
// is the sun's irradiance at normal incidence (Sky::sunIrradiance), with
// pixels many times larger than the sun and with the sun at any place in a
// pixel; and the projections' solid angle per pixel area, which that
// integral rests on, sums to the sphere's parts it should.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "baker/render/sky_image.h"
#include "baker/render/sun_disk_pixels.h"
#include "data_formats/angles.h"
#include "runtime/sky.h"

namespace skybake {
namespace {

// Midpoints per pixel side for the test's own integral of a pixel's solid
// angle: the density is smooth across a pixel, so its midpoint rule is
// within 1e-5 of the exact solid angle for these pixel sizes.
constexpr int kPixelQuadrature = 8;

// The pixel's solid angle: its area's integral of solidAnglePerPixelArea_sr,
// over the part inside the projection.
double pixelSolidAngle_sr(const SkyView& v, int x, int y) {
  double sum = 0.0;
  for (int j = 0; j < kPixelQuadrature; ++j) {
    for (int i = 0; i < kPixelQuadrature; ++i) {
      const double sx = x + (i + 0.5) / kPixelQuadrature, sy = y + (j + 0.5) / kPixelQuadrature;
      glm::dvec3 dir;
      if (directionAtImagePoint(v, sx, sy, dir)) sum += solidAnglePerPixelArea_sr(v, sx, sy);
    }
  }
  return sum / (kPixelQuadrature * kPixelQuadrature);
}

double imageSolidAngle_sr(const SkyView& v) {
  double sum = 0.0;
  for (int y = 0; y < v.height; ++y) {
    for (int x = 0; x < v.width; ++x) sum += pixelSolidAngle_sr(v, x, y);
  }
  return sum;
}

TEST(SunDiskPixels, ProjectionsCoverTheirSolidAngles) {
  SkyView latlong;
  latlong.projection = Projection::LatLong;
  latlong.width = 64;
  latlong.height = 32;
  // The whole sphere; the midpoint rule in zenith is within 1e-3 of it.
  EXPECT_NEAR(imageSolidAngle_sr(latlong), 4.0 * kPi, 1e-3 * 4.0 * kPi);
  SkyView fisheye;
  fisheye.projection = Projection::Fisheye;
  fisheye.fov_deg = 180.0;
  fisheye.width = fisheye.height = 64;
  // The upper hemisphere; the pixels cut by the circle are counted only
  // to their midpoints inside it, 1 % at this size.
  EXPECT_NEAR(imageSolidAngle_sr(fisheye), 2.0 * kPi, 0.01 * 2.0 * kPi);
  SkyView perspective;
  perspective.projection = Projection::Perspective;
  perspective.fov_deg = 60.0;
  perspective.width = 48;
  perspective.height = 32;
  // A rectangle of half-angles a and b on the image plane subtends
  // 4 asin(sin a sin b).
  const double half_width = std::tan(radiansFromDegrees(30.0));
  const double half_height = half_width * 32.0 / 48.0;
  const double a = std::atan(half_width), b = std::atan(half_height);
  const double expected = 4.0 * std::asin(std::sin(a) * std::sin(b));
  EXPECT_NEAR(imageSolidAngle_sr(perspective), expected, 1e-4 * expected);
}

TEST(SunDiskPixels, ImageHoldsTheSunsIrradianceInEveryProjection) {
  const Sky sky = Sky::load(SKYBAKE_TEST_BAKE_DIR "/earth.exr");
  SkyView base;
  base.altitude_m = 0.0;
  struct Case {
    Projection projection;
    int width, height;
    double fov_deg, sun_zenith_deg, sun_azimuth_deg;
  };
  // Pixels 3 to 20 sun radii across, the sun off the pixel grid's lines.
  const Case cases[] = {
      {Projection::LatLong, 64, 32, 180.0, 37.3, 0.0},    {Projection::LatLong, 256, 128, 180.0, 0.0, 0.0},
      {Projection::Fisheye, 64, 64, 180.0, 41.7, 12.0},   {Projection::Fisheye, 33, 33, 180.0, 3.1, 0.0},
      {Projection::Perspective, 48, 32, 20.0, 62.9, 0.0},
  };
  for (const Case& c : cases) {
    SkyView v = base;
    v.projection = c.projection;
    v.width = c.width;
    v.height = c.height;
    v.fov_deg = c.fov_deg;
    v.sun_zenith_deg = c.sun_zenith_deg;
    v.sun_azimuth_deg = c.sun_azimuth_deg;
    v.view_elevation_deg = 90.0 - c.sun_zenith_deg + 3.0;  // the sun a little below the image's centre
    v.view_azimuth_deg = c.sun_azimuth_deg + 2.0;
    SpectralImage sun_only{v.width, v.height, sky.channelCount(), {}};
    sun_only.radiance.assign(static_cast<size_t>(v.width) * v.height * sun_only.channels, 0.0f);
    addSunDisk(sky, v, sun_only);
    Spectrum integral(0.0f);
    for (int y = 0; y < v.height; ++y) {
      for (int x = 0; x < v.width; ++x) {
        const double solid_angle = pixelSolidAngle_sr(v, x, y);
        for (int ch = 0; ch < sun_only.channels; ++ch) {
          integral[ch] += static_cast<float>(sun_only.pixel(x, y)[ch] * solid_angle);
        }
      }
    }
    const glm::dvec3 sun = sunDirection(v);
    const Spectrum expected = sky.sunIrradiance(cameraPosition(sky, v), sun, sun);
    for (int ch = 0; ch < sky.channelCount(); ++ch) {
      // The disk's area from antialiased subsamples (0.1 %), the test's and
      // the render's pixel solid angles (1e-5), the transmittance averaged
      // over the disk rather than taken at its centre (1e-4 at 63 deg).
      EXPECT_NEAR(integral[ch], expected[ch], 0.005 * expected[ch])
          << "projection " << static_cast<int>(c.projection) << " " << c.width << "x" << c.height << ", sun "
          << c.sun_zenith_deg << " deg, channel " << ch;
    }
  }
}

TEST(SunDiskPixels, NoSunLeavesTheImageAlone) {
  const Sky sky = Sky::load(SKYBAKE_TEST_BAKE_DIR "/earth.exr");
  SkyView v;
  v.projection = Projection::LatLong;
  v.width = 64;
  v.height = 32;
  v.sun_disk = false;
  SpectralImage image{v.width, v.height, sky.channelCount(), {}};
  image.radiance.assign(static_cast<size_t>(v.width) * v.height * image.channels, 0.0f);
  addSunDisk(sky, v, image);
  for (float value : image.radiance) EXPECT_EQ(value, 0.0f);
}

}  // namespace
}  // namespace skybake

namespace skybake {
namespace {

// Under an eclipse the image holds the part of the sun the moon leaves:
// none in totality (the moon's limb 0.013 deg outside the sun's, closer
// than the subsamples' ramp), the exact uncovered share in a partial and an
// annular eclipse (Sky::sunIrradiance with the moon).
TEST(SunDiskPixels, TheMoonHidesItsShareOfTheDisk) {
  const Sky sky = Sky::load(SKYBAKE_TEST_BAKE_DIR "/earth.exr");
  SkyView v;
  v.projection = Projection::Perspective;
  v.width = 48;
  v.height = 32;
  v.fov_deg = 2.0;  // pixels a sixth of the sun's radius across: the crescent spans many
  v.sun_zenith_deg = 50.0;
  v.view_elevation_deg = 40.0;
  v.view_azimuth_deg = 0.0;
  const glm::dvec3 sun = sunDirection(v);
  for (auto [elevation_deg, radius_deg] : {std::array{40.0, 0.28}, std::array{40.3, 0.28}, std::array{40.0, 0.25}}) {
    v.moon = moonSeenFrom(sky, v, 0.0, elevation_deg, radius_deg);
    SpectralImage image{v.width, v.height, sky.channelCount(), {}};
    image.radiance.assign(static_cast<size_t>(v.width) * v.height * image.channels, 0.0f);
    addSunDisk(sky, v, image);
    Spectrum integral(0.0f);
    for (int y = 0; y < v.height; ++y) {
      for (int x = 0; x < v.width; ++x) {
        for (int ch = 0; ch < image.channels; ++ch) {
          integral[ch] += static_cast<float>(image.pixel(x, y)[ch] * pixelSolidAngle_sr(v, x, y));
        }
      }
    }
    const Spectrum expected = sky.sunIrradiance(cameraPosition(sky, v), sun, {sun, v.moon});
    for (int ch = 0; ch < sky.channelCount(); ++ch) {
      if (expected[ch] == 0.0f) {
        EXPECT_EQ(integral[ch], 0.0f) << "totality";
      } else {
        // As the whole disk's bound above.
        EXPECT_NEAR(integral[ch], expected[ch], 0.005 * expected[ch]) << "moon at " << elevation_deg << " deg";
      }
    }
  }
}

}  // namespace
}  // namespace skybake
