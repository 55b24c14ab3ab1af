#include "baker/render/sky_image.h"

#include "runtime/atmosphere_ray.h"

#include <omp.h>

#include <cmath>

#include <glm/geometric.hpp>

namespace skybake {
namespace {

// The view direction through pixel centre (x, y), or false outside the projection.
bool pixelDirection(const SkyView& v, int x, int y, glm::dvec3& dir) {
  const double u = (x + 0.5) / v.width;
  const double w = (y + 0.5) / v.height;
  switch (v.projection) {
    case Projection::LatLong: {
      // The sun's azimuth in the middle column, the zenith on the top row.
      dir = directionFromZenithAzimuth(w * kPi, radiansFromDegrees(v.sun_azimuth_deg) + (u - 0.5) * 2.0 * kPi);
      return true;
    }
    case Projection::Fisheye: {
      const double scale = std::min(v.width, v.height);
      const double px = (2.0 * (x + 0.5) - v.width) / scale;
      const double py = (v.height - 2.0 * (y + 0.5)) / scale;
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

// What a pixel sees along `dir`: what the viewer receives (sky and lit
// ground; the air alone where the bake left out ground irradiance), plus the
// sun disk seen through the air.
Spectrum radianceAlong(const Sky& sky, const glm::dvec3& camera, const glm::dvec3& dir, const glm::dvec3& sun) {
  const RadianceAndTransmittance received =
      sky.outputs().ground_irradiance ? sky.receivedRadiance(camera, dir, sun) : sky.skyRadiance(camera, dir, sun);
  Spectrum radiance = received.radiance;
  const AtmosphereRay ray =
      atmosphereRay(sky.atmosphere().bottom_radius_m, sky.atmosphere().top_radius_m, camera, dir, 0.0);
  if (!ray.ends_on_ground && glm::dot(dir, sun) > std::cos(sky.atmosphere().sun_angular_radius_rad)) {
    radiance += received.transmittance * sky.solarRadiance();
  }
  return radiance;
}

}  // namespace

glm::dvec3 directionFromZenithAzimuth(double zenith_rad, double azimuth_rad) {
  return {std::sin(zenith_rad) * std::cos(azimuth_rad), std::sin(zenith_rad) * std::sin(azimuth_rad),
          std::cos(zenith_rad)};
}

glm::dvec3 sunDirection(const SkyView& v) {
  return directionFromZenithAzimuth(radiansFromDegrees(v.sun_zenith_deg), radiansFromDegrees(v.sun_azimuth_deg));
}

PerspectiveFrame perspectiveFrame(const SkyView& v) {
  const double azimuth = radiansFromDegrees(v.view_azimuth_deg);
  const double elevation = radiansFromDegrees(v.view_elevation_deg);
  PerspectiveFrame f;
  f.forward = {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation)};
  f.right = glm::normalize(glm::cross(f.forward, glm::dvec3(0.0, 0.0, 1.0)));
  f.up = glm::cross(f.right, f.forward);
  f.half_width = std::tan(radiansFromDegrees(v.fov_deg) * 0.5);
  f.half_height = f.half_width * v.height / v.width;
  return f;
}

std::array<int, 3> displayChannels(const std::vector<double>& wavelengths_nm) {
  auto nearest = [&](double target_nm) {
    int best = 0;
    for (int c = 1; c < static_cast<int>(wavelengths_nm.size()); ++c) {
      if (std::abs(wavelengths_nm[c] - target_nm) < std::abs(wavelengths_nm[best] - target_nm)) best = c;
    }
    return best;
  };
  return {nearest(680.0), nearest(550.0), nearest(440.0)};
}

std::vector<float> renderSkyRadiance(const Sky& sky, const SkyView& v) {
  std::vector<float> image(static_cast<size_t>(v.width) * v.height * 3, 0.0f);
  const glm::dvec3 camera(0.0, 0.0, sky.atmosphere().bottom_radius_m + v.altitude_m);
  const glm::dvec3 sun = sunDirection(v);
  const std::vector<double>& wavelengths = sky.atmosphere().wavelengths_nm;
  const std::array<int, 3> rgb = displayChannels(wavelengths);
#pragma omp parallel for schedule(dynamic)
  for (int y = 0; y < v.height; ++y) {
    for (int x = 0; x < v.width; ++x) {
      glm::dvec3 dir;
      if (!pixelDirection(v, x, y, dir)) continue;
      const Spectrum radiance = radianceAlong(sky, camera, dir, sun);
      float* pixel = &image[(static_cast<size_t>(y) * v.width + x) * 3];
      for (int c = 0; c < 3; ++c) pixel[c] = radiance[rgb[c]];
    }
  }
  return image;
}

namespace {

// Narkowicz's fit of the ACES filmic curve.
double acesFilm(double x) { return std::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0); }

double srgbEncode(double linear) {
  const double v = std::clamp(linear, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

}  // namespace

std::vector<unsigned char> encodeForDisplay(const std::vector<float>& linear_rgb, double exposure, ToneMap tone_map) {
  std::vector<unsigned char> out(linear_rgb.size());
  for (size_t i = 0; i < linear_rgb.size(); ++i) {
    double v = linear_rgb[i] * exposure;
    if (tone_map == ToneMap::Reinhard) v = v / (1.0 + v);
    if (tone_map == ToneMap::Aces) v = acesFilm(v);
    out[i] = static_cast<unsigned char>(std::lround(srgbEncode(v) * 255.0));
  }
  return out;
}

}  // namespace skybake
