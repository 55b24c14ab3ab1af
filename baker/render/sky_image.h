// Images of a baked sky as seen by a camera: the projections, what a pixel
// sees (sky, sun disk, lit ground), and display encoding.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

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
};

// The unit vector at `zenith_rad` from +z and `azimuth_rad` from +x toward +y.
glm::dvec3 directionFromZenithAzimuth(double zenith_rad, double azimuth_rad);

// The channels an image shows as R, G and B: the bake's channels nearest
// 680, 550 and 440 nm.
std::array<int, 3> displayChannels(const std::vector<double>& wavelengths_nm);

// The sun's direction in a view's frame (its zenith and azimuth angles).
glm::dvec3 sunDirection(const SkyView& view);

// A perspective view's camera frame: unit vectors along the view, to the
// image's right and up, and the image plane's half extents at distance 1.
struct PerspectiveFrame {
  glm::dvec3 forward, right, up;
  double half_width, half_height;
};
PerspectiveFrame perspectiveFrame(const SkyView& view);

// Linear RGB radiance, W m^-2 sr^-1 nm^-1, width * height * 3 floats, rows top
// to bottom. R, G and B are the bake's channels nearest 680, 550 and 440 nm.
// Pixels outside the projection (the corners of a fisheye) are 0.
std::vector<float> renderSkyRadiance(const Sky& sky, const SkyView& view);

enum class ToneMap { None, Reinhard, Aces };

// Scales by `exposure`, tone-maps and encodes as 8-bit sRGB.
std::vector<unsigned char> encodeForDisplay(const std::vector<float>& linear_rgb, double exposure, ToneMap tone_map);

}  // namespace skybake
