#include "baker/render/sky_image.h"

#include "data_formats/queries/local_frame.h"
#include "runtime/colour/srgb_transfer.h"

#include <omp.h>

#include <cmath>

#include <glm/geometric.hpp>

namespace skybake {
namespace {

// What a pixel sees along `dir`, the sun disk aside: what the viewer
// receives (sky and lit ground; the air alone where the bake left out
// ground irradiance).
Spectrum radianceAlong(const Sky& sky, const glm::dvec3& camera, const glm::dvec3& dir, const Sunlight& sun) {
  return (sky.outputs().ground_irradiance ? sky.receivedRadiance(camera, dir, sun) : sky.skyRadiance(camera, dir, sun))
      .radiance;
}

}  // namespace

glm::dvec3 sunDirection(const SkyView& v) {
  return directionFromZenithAzimuth(radiansFromDegrees(v.sun_zenith_deg), radiansFromDegrees(v.sun_azimuth_deg));
}

glm::dvec3 cameraPosition(const Sky& sky, const SkyView& v) {
  return cameraAtAltitude(sky.atmosphere().bottom_radius_m, v.altitude_m);
}

Moon moonSeenFrom(const Sky& sky, const SkyView& v, double azimuth_deg, double elevation_deg,
                  double angular_radius_deg) {
  const glm::dvec3 dir =
      directionFromZenithAzimuth(radiansFromDegrees(90.0 - elevation_deg), radiansFromDegrees(azimuth_deg));
  return Moon::seenFrom(cameraPosition(sky, v), dir, radiansFromDegrees(angular_radius_deg));
}

PerspectiveFrame perspectiveFrame(const SkyView& v) {
  const double azimuth = radiansFromDegrees(v.view_azimuth_deg);
  const double elevation = radiansFromDegrees(v.view_elevation_deg);
  PerspectiveFrame f;
  f.forward = directionFromElevationAzimuth(elevation, azimuth);
  f.right = glm::normalize(glm::cross(f.forward, glm::dvec3(0.0, 0.0, 1.0)));
  f.up = glm::cross(f.right, f.forward);
  f.half_width = std::tan(radiansFromDegrees(v.fov_deg) * 0.5);
  f.half_height = f.half_width * v.height / v.width;
  return f;
}

bool directionAtImagePoint(const SkyView& v, double x, double y, glm::dvec3& dir) {
  const double u = x / v.width;
  const double w = y / v.height;
  switch (v.projection) {
    case Projection::LatLong: {
      // The sun's azimuth in the middle column, the zenith on the top row.
      dir = directionFromZenithAzimuth(w * kPi, radiansFromDegrees(v.sun_azimuth_deg) + (u - 0.5) * 2.0 * kPi);
      return true;
    }
    case Projection::Fisheye: {
      const double scale = std::min(v.width, v.height);
      const double px = (2.0 * x - v.width) / scale;
      const double py = (v.height - 2.0 * y) / scale;
      const double rho = std::sqrt(px * px + py * py);
      if (rho > 1.0) return false;
      // The sun's azimuth toward the top of the image.
      dir = directionFromZenithAzimuth(rho * radiansFromDegrees(v.fov_deg) * 0.5,
                                       radiansFromDegrees(v.sun_azimuth_deg) + std::atan2(px, py));
      return true;
    }
    case Projection::Perspective: {
      const PerspectiveFrame f = perspectiveFrame(v);
      dir = glm::normalize(f.forward + f.right * ((2.0 * u - 1.0) * f.half_width) +
                           f.up * ((1.0 - 2.0 * w) * f.half_height));
      return true;
    }
  }
  return false;
}

double solidAnglePerPixelArea_sr(const SkyView& v, double x, double y) {
  switch (v.projection) {
    case Projection::LatLong: {
      // dOmega = sin(zenith) dzenith dazimuth, pi / height and 2 pi / width per pixel.
      return std::sin(y / v.height * kPi) * (kPi / v.height) * (2.0 * kPi / v.width);
    }
    case Projection::Fisheye: {
      // Equidistant: zenith = k rho with k radians per pixel of radius, so
      // dOmega = sin(zenith) dzenith dazimuth = k^2 sin(zenith) / zenith dA.
      const double scale = std::min(v.width, v.height);
      const double k = radiansFromDegrees(v.fov_deg) * 0.5 * 2.0 / scale;
      const double zenith = k * std::hypot(x - 0.5 * v.width, y - 0.5 * v.height);
      return k * k * (zenith > 0.0 ? std::sin(zenith) / zenith : 1.0);
    }
    case Projection::Perspective: {
      // A pinhole at distance 1 from its image plane: dOmega = dA cos^3 of
      // the angle off the axis.
      const PerspectiveFrame f = perspectiveFrame(v);
      const double a = (2.0 * x / v.width - 1.0) * f.half_width;
      const double b = (1.0 - 2.0 * y / v.height) * f.half_height;
      const double plane_area = (2.0 * f.half_width / v.width) * (2.0 * f.half_height / v.height);
      return plane_area / std::pow(1.0 + a * a + b * b, 1.5);
    }
  }
  return 0.0;
}

SpectralImage renderSkyRadiance(const Sky& sky, const SkyView& v) {
  SpectralImage image{v.width, v.height, sky.channelCount(), {}};
  image.radiance.assign(static_cast<size_t>(v.width) * v.height * image.channels, 0.0f);
  const glm::dvec3 camera = cameraPosition(sky, v);
  Sunlight sun{sunDirection(v), v.moon};
  // A camera in the atmosphere starts every ray where it is: its skylight
  // share under an eclipse is computed once.
  if (v.moon.present() && glm::length(camera) <= sky.atmosphere().top_radius_m) {
    sun.camera_skylight = sky.eclipseSkylight(camera, sun);
  }
#pragma omp parallel for schedule(dynamic)
  for (int y = 0; y < v.height; ++y) {
    for (int x = 0; x < v.width; ++x) {
      glm::dvec3 dir;
      if (!directionAtImagePoint(v, x + 0.5, y + 0.5, dir)) continue;
      const Spectrum radiance = radianceAlong(sky, camera, dir, sun);
      float* pixel = image.pixel(x, y);
      for (int c = 0; c < image.channels; ++c) pixel[c] = radiance[c];
    }
  }
  return image;
}

std::vector<unsigned char> encodeForDisplay(const std::vector<float>& linear_rgb, double exposure, ToneMap tone_map) {
  const int kernel_tone_map = tone_map == ToneMap::Reinhard ? SKYBAKE_TONE_MAP_REINHARD
                              : tone_map == ToneMap::Aces   ? SKYBAKE_TONE_MAP_ACES
                                                            : SKYBAKE_TONE_MAP_NONE;
  std::vector<unsigned char> out(linear_rgb.size());
  for (size_t i = 0; i < linear_rgb.size(); ++i) {
    const double encoded = kernel::skybakeDisplayValue(linear_rgb[i], exposure, kernel_tone_map);
    out[i] = static_cast<unsigned char>(std::lround(encoded * 255.0));
  }
  return out;
}

}  // namespace skybake
