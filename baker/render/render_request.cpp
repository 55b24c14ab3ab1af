#include "baker/render/render_request.h"

#include <cmath>

#include <fmt/format.h>

#include "baker/validation/validation_queries.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

[[noreturn]] void refuse(const std::string& name, const std::string& value, const std::string& reason) {
  throwBadInput(fmt::format("{} = {}: {}", name, value, reason));
}

void requireFiniteIn(const std::string& name, double value, double low, double high) {
  if (!std::isfinite(value) || value < low || value > high) {
    refuse(name, fmt::format("{}", value), fmt::format("must be a finite number in [{}, {}]", low, high));
  }
}

}  // namespace

RenderRequestNames pythonRenderRequestNames() {
  return {"altitude_m", "sun_zenith_deg",     "sun_azimuth_deg",  "projection", "fov_deg",
          "size",       "view_elevation_deg", "view_azimuth_deg", "moon"};
}

SkyView renderView(const RenderRequest& r, const RenderRequestNames& names) {
  SkyView v;
  requireFiniteIn(names.altitude_m, r.altitude_m, -kMaxQueryAltitude_m, kMaxQueryAltitude_m);
  requireFiniteIn(names.sun_zenith_deg, r.sun_zenith_deg, 0.0, kMaxZenithAngle_deg);
  requireFiniteIn(names.sun_azimuth_deg, r.sun_azimuth_deg, -kMaxAzimuth_deg, kMaxAzimuth_deg);
  v.altitude_m = r.altitude_m;
  v.sun_zenith_deg = r.sun_zenith_deg;
  v.sun_azimuth_deg = r.sun_azimuth_deg;
  if (r.projection == "latlong") {
    v.projection = Projection::LatLong;
  } else if (r.projection == "perspective") {
    v.projection = Projection::Perspective;
  } else if (r.projection == "fisheye") {
    v.projection = Projection::Fisheye;
  } else {
    refuse(names.projection, r.projection, "must be fisheye, latlong or perspective");
  }
  const bool perspective = v.projection == Projection::Perspective;
  v.fov_deg = r.fov_deg.value_or(perspective ? 90.0 : 180.0);
  requireFiniteIn(names.fov_deg, v.fov_deg, kMinFieldOfView_deg, kMaxFieldOfView_deg);
  if (perspective && v.fov_deg >= kMaxPerspectiveFieldOfView_deg) {
    refuse(names.fov_deg, fmt::format("{}", v.fov_deg),
           fmt::format("a perspective camera needs less than {} degrees", kMaxPerspectiveFieldOfView_deg));
  }
  v.width = v.projection == Projection::LatLong ? 1024 : 512;
  v.height = 512;
  if (r.size) {
    const auto [width, height] = *r.size;
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide) {
      refuse(names.size, fmt::format("{}x{}", width, height),
             fmt::format("each side must be in [1, {}]", kMaxImageSide));
    }
    v.width = width;
    v.height = height;
  }
  requireFiniteIn(names.view_elevation_deg, r.view_elevation_deg, -90.0, 90.0);
  v.view_elevation_deg = r.view_elevation_deg;
  v.view_azimuth_deg = r.view_azimuth_deg.value_or(v.sun_azimuth_deg);
  requireFiniteIn(names.view_azimuth_deg, v.view_azimuth_deg, -kMaxAzimuth_deg, kMaxAzimuth_deg);
  v.sun_disk = r.sun_disk;
  if (r.moon_deg) {
    const auto [azimuth, elevation, radius] = *r.moon_deg;
    const std::string text = fmt::format("{},{},{}", azimuth, elevation, radius);
    if (!std::isfinite(azimuth) || !std::isfinite(elevation) || !std::isfinite(radius)) {
      refuse(names.moon, text, "must be three finite numbers of degrees");
    }
    if (std::abs(azimuth) > kMaxAzimuth_deg) {
      refuse(names.moon, text, fmt::format("the azimuth must be in [-{0}, {0}] degrees", kMaxAzimuth_deg));
    }
    if (std::abs(elevation) > 90.0) refuse(names.moon, text, "the elevation must be in [-90, 90] degrees");
    if (!(radius > 0.0) || radius > kMaxMoonAngularRadius_deg) {
      refuse(names.moon, text, fmt::format("the angular radius must be in (0, {}] degrees", kMaxMoonAngularRadius_deg));
    }
  }
  return v;
}

void placeMoon(const RenderRequest& r, const Sky& sky, SkyView& view) {
  if (!r.moon_deg) return;
  const auto [azimuth, elevation, radius] = *r.moon_deg;
  view.moon = moonSeenFrom(sky, view, azimuth, elevation, radius);
}

}  // namespace skybake
