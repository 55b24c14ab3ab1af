// The command line's way of describing a scene, in Python: altitudes and
// zenith/azimuth angles in the local frame (data_formats/queries/local_frame.h)
// turned into the lookups' vectors, and Sky.render's images (the same views
// as `skybake render`, baker/render/render_request.h).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "baker/cli/available_memory.h"
#include "baker/python/python_bindings.h"
#include "baker/render/image_colour.h"
#include "baker/render/render_request.h"
#include "baker/render/sky_image.h"
#include "data_formats/error.h"
#include "data_formats/queries/local_frame.h"
#include "runtime/colour/luminance.h"
#include "runtime/sky.h"

namespace py = pybind11;

namespace skybake::python {
namespace {

using Values = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Memory per pixel of Sky.render's result: the spectral floats while the
// image is made, the returned floats (at most as many), and linear sRGB.
constexpr uint64_t kRenderBytesPerPixelChannel = 2 * sizeof(float);
constexpr uint64_t kRenderBytesPerPixel = 3 * sizeof(float);

// (n, 3) rows, row i the vector vectorAt(i).
template <typename VectorAt>
py::array_t<double> vectorRows(size_t n, VectorAt vectorAt) {
  py::array_t<double> out({static_cast<py::ssize_t>(n), py::ssize_t{3}});
  double* o = out.mutable_data();
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec3 v = vectorAt(i);
    o[3 * i] = v.x;
    o[3 * i + 1] = v.y;
    o[3 * i + 2] = v.z;
  }
  return out;
}

// (N,) altitudes in metres to (N, 3) positions above the +z pole.
py::array_t<double> positionsAtAltitude(double bottom_radius_m, const Values& altitude_m) {
  const double* altitude = altitude_m.data();
  return vectorRows(static_cast<size_t>(altitude_m.size()),
                    [&](size_t i) { return cameraAtAltitude(bottom_radius_m, altitude[i]); });
}

// (N,) zenith and azimuth angles in degrees to (N, 3) unit directions.
py::array_t<double> directionsAtAngles(const Values& zenith_deg, const Values& azimuth_deg) {
  const size_t n = static_cast<size_t>(zenith_deg.size());
  if (static_cast<size_t>(azimuth_deg.size()) != n) {
    throw Error(ErrorKind::BadInput, "zenith and azimuth angles: needs as many of each");
  }
  const double *zenith = zenith_deg.data(), *azimuth = azimuth_deg.data();
  return vectorRows(n, [&](size_t i) { return directionFromZenithAzimuthDeg(zenith[i], azimuth[i]); });
}

py::array_t<float> render(const Sky& sky, const RenderRequest& request, const std::string& channels) {
  if (channels != "rgb" && channels != "spectral") {
    throw Error(ErrorKind::BadInput, fmt::format("channels = {}: must be rgb or spectral", channels));
  }
  SkyView view = renderView(request, pythonRenderRequestNames());
  placeMoon(request, sky, view);
  requireMemoryAvailable(fmt::format("size = {}x{}: the image", view.width, view.height),
                         static_cast<uint64_t>(view.width) * static_cast<uint64_t>(view.height) *
                             (kRenderBytesPerPixel + kRenderBytesPerPixelChannel * sky.channelCount()));
  std::vector<float> pixels;
  int depth = 3;
  {
    py::gil_scoped_release release;
    SpectralImage image =
        renderEveryChannel([](const Sky& group, const SkyView& v) { return renderSkyRadiance(group, v); }, sky, view);
    if (channels == "rgb") {
      pixels = linearSrgbImage(image, sky.atmosphere(), colour::kMaxLuminousEfficacy_lm_per_W);
    } else {
      depth = image.channels;
      pixels = std::move(image.radiance);
    }
  }
  py::array_t<float> out(
      {static_cast<py::ssize_t>(view.height), static_cast<py::ssize_t>(view.width), static_cast<py::ssize_t>(depth)});
  std::copy(pixels.begin(), pixels.end(), out.mutable_data());
  return out;
}

}  // namespace

void registerScene(py::module_& m) {
  m.def("_positions_at_altitude", &positionsAtAltitude, py::arg("bottom_radius_m"), py::arg("altitude_m"));
  m.def("_directions_at_angles", &directionsAtAngles, py::arg("zenith_deg"), py::arg("azimuth_deg"));
  m.def("_render",
        [](const Sky& sky, double altitude_m, double sun_zenith_deg, double sun_azimuth_deg,
           const std::string& projection, std::optional<double> fov_deg, std::optional<std::array<int, 2>> size,
           double view_elevation_deg, std::optional<double> view_azimuth_deg, bool sun_disk,
           std::optional<std::array<double, 3>> moon_deg, const std::string& channels) {
          RenderRequest r;
          r.altitude_m = altitude_m;
          r.sun_zenith_deg = sun_zenith_deg;
          r.sun_azimuth_deg = sun_azimuth_deg;
          r.projection = projection;
          r.fov_deg = fov_deg;
          r.size = size;
          r.view_elevation_deg = view_elevation_deg;
          r.view_azimuth_deg = view_azimuth_deg;
          r.sun_disk = sun_disk;
          r.moon_deg = moon_deg;
          return render(sky, r, channels);
        });
}

}  // namespace skybake::python
