// Images of a baked sky as seen by a camera: the projections, what a pixel
// sees (sky and lit ground; the sun disk is added by sun_disk_pixels.h), and
// display encoding.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "data_formats/angles.h"
#include "runtime/sky.h"

namespace skybake {

enum class Projection {
  Fisheye,      // looking straight up, zenith angle proportional to radius (equidistant)
  LatLong,      // full sphere, azimuth across, zenith angle down (an environment map)
  Perspective,  // pinhole camera looking toward view_azimuth_deg
};

struct SkyView {
  double altitude_m = 0.0;
  double sun_zenith_deg = 30.0;
  double sun_azimuth_deg = 0.0;
  Projection projection = Projection::Fisheye;
  double fov_deg = 180.0;            // fisheye: full cone angle; perspective: horizontal field of view
  double view_azimuth_deg = 0.0;     // perspective: where the camera looks
  double view_elevation_deg = 10.0;  // perspective: above the horizontal
  int width = 512;
  int height = 512;
  bool sun_disk = true;  // false: the sun disk is left out (a renderer adds its own directional light)
  Moon moon;             // a solar eclipse's moon (none by default): see moonSeenFrom
};

// The moon at `azimuth_deg` (in the view's frame, as the sun's) and
// `elevation_deg` above the horizontal, `angular_radius_deg` in radius, seen
// from the view's camera at the mean lunar distance.
Moon moonSeenFrom(const Sky& sky, const SkyView& view, double azimuth_deg, double elevation_deg,
                  double angular_radius_deg);

// Spectral radiance per pixel, W m^-2 sr^-1 nm^-1: `channels` floats per
// pixel in the bake's channel order, rows top to bottom.
struct SpectralImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> radiance;
  float* pixel(int x, int y) { return &radiance[(static_cast<size_t>(y) * width + x) * channels]; }
  const float* pixel(int x, int y) const { return &radiance[(static_cast<size_t>(y) * width + x) * channels]; }
};

// The sun's direction in a view's frame (its zenith and azimuth angles).
glm::dvec3 sunDirection(const SkyView& view);

// The camera's position, m from the planet's centre: above the frame's
// origin on the +z axis, at the view's altitude.
glm::dvec3 cameraPosition(const Sky& sky, const SkyView& view);

// A perspective view's camera frame: unit vectors along the view, to the
// image's right and up, and the image plane's half extents at distance 1.
struct PerspectiveFrame {
  glm::dvec3 forward, right, up;
  double half_width, half_height;
};
PerspectiveFrame perspectiveFrame(const SkyView& view);

// The view direction through image point (x, y), in pixels from the image's
// top-left corner (a pixel's centre is at +0.5), or false outside the
// projection.
bool directionAtImagePoint(const SkyView& view, double x, double y, glm::dvec3& dir);

// Solid angle per unit image area at image point (x, y), sr per pixel^2:
// what a pixel's part around that point sees of the sphere.
double solidAnglePerPixelArea_sr(const SkyView& view, double x, double y);

// What each pixel centre sees: sky radiance and the lit ground (the air
// alone where the bake left out ground irradiance), without the sun disk.
// Pixels outside the projection (the corners of a fisheye) are 0.
SpectralImage renderSkyRadiance(const Sky& sky, const SkyView& view);

enum class ToneMap { None, Reinhard, Aces };

// Scales linear sRGB by `exposure`, tone-maps and encodes as 8-bit sRGB.
std::vector<unsigned char> encodeForDisplay(const std::vector<float>& linear_rgb, double exposure, ToneMap tone_map);

}  // namespace skybake
