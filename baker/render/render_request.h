// What a render asks for, as its user states it (`skybake render`'s options,
// the Python module's Sky.render arguments), turned into a SkyView: the
// limits and the defaults that depend on the projection live here once.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "baker/render/sky_image.h"
#include "baker/render/sun_disk_pixels.h"
#include "runtime/sky.h"

namespace skybake {

struct RenderRequest {
  double altitude_m = 0.0;
  double sun_zenith_deg = 0.0;
  double sun_azimuth_deg = 0.0;
  std::string projection = "fisheye";      // fisheye, latlong or perspective
  std::optional<double> fov_deg;           // default: 180 (fisheye), 90 (perspective)
  std::optional<std::array<int, 2>> size;  // width, height; default 512x512, latlong 1024x512
  double view_elevation_deg = 10.0;        // perspective only
  std::optional<double> view_azimuth_deg;  // perspective only; default: the sun's
  bool sun_disk = true;
  // A solar eclipse's moon: azimuth, elevation and angular radius, degrees,
  // seen from the camera (moonSeenFrom).
  std::optional<std::array<double, 3>> moon_deg;
};

// The names a caller's user knows each field by, for refusals
// ("--fov-deg = 200: ..." on the command line, "fov_deg = 200: ..." in Python).
struct RenderRequestNames {
  std::string altitude_m, sun_zenith_deg, sun_azimuth_deg, projection, fov_deg, size, view_elevation_deg,
      view_azimuth_deg, moon;
};
// The Python module's names: the arguments of Sky.render.
RenderRequestNames pythonRenderRequestNames();

// --fov-deg: below a degree the view is finer than any table resolves; more
// than a full turn is not a field of view.
inline constexpr double kMinFieldOfView_deg = 1.0;
inline constexpr double kMaxFieldOfView_deg = 360.0;
// A perspective projection's image plane grows as tan(fov / 2): at 179
// degrees it is already 229 times the focal length, at 180 infinite.
inline constexpr double kMaxPerspectiveFieldOfView_deg = 179.0;
// Largest image side: 16k pixels a side is far beyond any preview and keeps
// the spectral float image within 4 GiB (four channels).
inline constexpr int kMaxImageSide = 16384;

// The view the request describes, every value checked (a non-finite or
// out-of-range one throws Error(BadInput) "<name> = <value>: <reason>"), so
// that a bad request is refused before a bake is read; without its moon,
// which placeMoon adds once the bake (its planet) is known.
SkyView renderView(const RenderRequest& request, const RenderRequestNames& names);

// The request's moon, if any, seen from the view's camera above `sky`'s planet.
void placeMoon(const RenderRequest& request, const Sky& sky, SkyView& view);

// Every channel's image with the sun disk added, from `render(group, view)`
// (a lane group's SpectralImage without the disk) for each lane group of the
// bake, its channels put in their place among the bake's.
template <typename RenderGroup>
SpectralImage renderEveryChannel(const RenderGroup& render, const Sky& sky, const SkyView& view) {
  if (sky.laneGroupCount() == 1) {
    SpectralImage image = render(sky, view);
    addSunDisk(sky, view, image);
    return image;
  }
  const size_t pixels = static_cast<size_t>(view.width) * view.height;
  const size_t channels = static_cast<size_t>(sky.channelCount());
  SpectralImage joined{view.width, view.height, sky.channelCount(), std::vector<float>(pixels * channels, 0.0f)};
  for (int g = 0; g < sky.laneGroupCount(); ++g) {
    const Sky& group = sky.laneGroup(g);
    SpectralImage part = render(group, view);
    addSunDisk(group, view, part);
    const size_t first = static_cast<size_t>(sky.laneGroupFirstChannel(g));
    for (size_t p = 0; p < pixels; ++p) {
      for (int c = 0; c < part.channels; ++c) {
        joined.radiance[p * channels + first + c] = part.radiance[p * part.channels + c];
      }
    }
  }
  return joined;
}

}  // namespace skybake
