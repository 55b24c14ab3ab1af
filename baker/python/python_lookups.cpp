// skybake._skybake.Sky: Sky's lookups over N rows at once. The Python layer
// (skybake/__init__.py) broadcasts its arguments and hands over C-contiguous
// float64 arrays of shape (N, 3) (directions, positions in metres from the
// planet's centre) and (N,) (lengths in metres); results are float32 arrays
// of shape (N, channels), the lookups' own Spectrum values unchanged. The GIL
// is released during the lookups, and calls of many rows are split over
// threads (every Sky lookup is const and thread-safe).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <initializer_list>
#include <string>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>
#include "baker/python/python_bindings.h"
#include "data_formats/error.h"

#include "runtime/lookup_geometry.h"
#include "runtime/sky.h"

namespace py = pybind11;

namespace skybake::python {
namespace {

using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Spectra = py::array_t<float>;

// Fewer rows than this per thread cost more in thread start-up (tens of
// microseconds) than the lookups they would take off the first thread.
constexpr size_t kMinRowsPerThread = 4096;

size_t rowCount(const Rows& a, int columns, const char* name) {
  if (a.ndim() != 2 || a.shape(1) != columns) {
    throw Error(ErrorKind::BadInput, std::string(name) + ": needs shape (N, " + std::to_string(columns) + ")");
  }
  return static_cast<size_t>(a.shape(0));
}

glm::dvec3 row3(const double* base, size_t i) { return {base[3 * i], base[3 * i + 1], base[3 * i + 2]}; }

// Runs body(first, last) over [0, n) on as many threads as the rows warrant,
// without the GIL; rethrows the first exception a thread raised.
template <typename Body>
void forRows(size_t n, Body body) {
  py::gil_scoped_release release;
  const size_t hardware = std::max(1u, std::thread::hardware_concurrency());
  const size_t threads = std::clamp<size_t>(n / kMinRowsPerThread, 1, hardware);
  std::vector<std::exception_ptr> errors(threads);
  auto run = [&](size_t t) {
    try {
      body(n * t / threads, n * (t + 1) / threads);
    } catch (...) {
      errors[t] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (size_t t = 1; t < threads; ++t) pool.emplace_back(run, t);
  run(0);
  for (std::thread& thread : pool) thread.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

Spectra spectra(size_t n, int channels) {
  return Spectra({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(channels)});
}

// Arrays of shape (n, channels), one per Spectrum of a lookup's result
// (lookupParts order), filled with row_lookup(group, i) of every row i on
// every lane group of the bake (Sky::writeEveryChannel): any lookup, one
// code path for all of them.
template <size_t Parts, typename RowLookup>
std::array<Spectra, Parts> lookupRows(const Sky& sky, size_t n, RowLookup row_lookup) {
  const int channels = sky.channelCount();
  std::array<Spectra, Parts> out;
  std::array<float*, Parts> base{};
  for (size_t k = 0; k < Parts; ++k) {
    out[k] = spectra(n, channels);
    base[k] = out[k].mutable_data();
  }
  forRows(n, [&](size_t first, size_t last) {
    for (size_t i = first; i < last; ++i) {
      std::array<float*, Parts> row{};
      for (size_t k = 0; k < Parts; ++k) row[k] = base[k] + i * static_cast<size_t>(channels);
      sky.writeEveryChannel([&](const Sky& group) { return row_lookup(group, i); }, row);
    }
  });
  return out;
}

py::tuple pair(std::array<Spectra, 2>&& arrays) { return py::make_tuple(arrays[0], arrays[1]); }

void requireRows(size_t n, std::initializer_list<size_t> others) {
  for (size_t other : others) {
    if (other != n) throw Error(ErrorKind::BadInput, "the arguments' rows differ in number");
  }
}

py::tuple radianceRows(const Sky& sky, const Rows& from, const Rows& to, const Rows& sun, const Rows& shadow_m,
                       bool to_point) {
  const size_t n = rowCount(from, 3, "camera_m");
  requireRows(n, {rowCount(to, 3, to_point ? "point_m" : "view_dir"), rowCount(sun, 3, "sun_dir"),
                  static_cast<size_t>(shadow_m.size())});
  const double *a = from.data(), *b = to.data(), *s = sun.data(), *shadow = shadow_m.data();
  return pair(lookupRows<2>(sky, n, [&](const Sky& group, size_t i) {
    return to_point ? group.radianceToPoint(row3(a, i), row3(b, i), row3(s, i), shadow[i])
                    : group.skyRadiance(row3(a, i), row3(b, i), row3(s, i), shadow[i]);
  }));
}

// The eclipse lookups: a moon per row (its centre, m from the planet's
// centre, and its radius, m).
enum class EclipseLookup { SkyRadiance, Irradiance, RadianceToPoint };

py::tuple eclipseRows(const Sky& sky, const Rows& camera, const Rows& view, const Rows& sun, const Rows& moon_centre,
                      const Rows& moon_radius, EclipseLookup lookup) {
  const bool irradiance = lookup == EclipseLookup::Irradiance;
  const size_t n = rowCount(camera, 3, irradiance ? "point_m" : "camera_m");
  const char* second_name = irradiance ? "normal" : lookup == EclipseLookup::RadianceToPoint ? "point_m" : "view_dir";
  requireRows(n, {rowCount(view, 3, second_name), rowCount(sun, 3, "sun_dir"),
                  rowCount(moon_centre, 3, "moon centre_m"), static_cast<size_t>(moon_radius.size())});
  const double *a = camera.data(), *b = view.data(), *s = sun.data(), *m = moon_centre.data(),
               *radius = moon_radius.data();
  auto sunlight = [&](size_t i) { return Sunlight{row3(s, i), Moon{row3(m, i), radius[i]}}; };
  if (irradiance) {
    return pair(lookupRows<2>(
        sky, n, [&](const Sky& group, size_t i) { return group.irradiance(row3(a, i), row3(b, i), sunlight(i)); }));
  }
  return pair(lookupRows<2>(sky, n, [&](const Sky& group, size_t i) {
    return lookup == EclipseLookup::RadianceToPoint ? group.radianceToPoint(row3(a, i), row3(b, i), sunlight(i))
                                                    : group.skyRadiance(row3(a, i), row3(b, i), sunlight(i));
  }));
}

// The atmosphere the file states, every per-channel value in channel order
// (a spectral bake's from its lane groups).
py::dict atmosphereDict(const Sky& sky) {
  const AtmosphereParameters& a = sky.atmosphere();
  auto spectrum = [&](Spectrum AtmosphereParameters::*quantity) {
    std::vector<double> v;
    for (int g = 0; g < sky.laneGroupCount(); ++g) {
      const Sky& group = sky.laneGroup(g);
      for (int c = 0; c < group.channelCount(); ++c) v.push_back((group.atmosphere().*quantity)[c]);
    }
    return v;
  };
  py::dict d;
  d["wavelengths_nm"] = a.wavelengths_nm;
  d["channel_kind"] = a.storesCieXyz() ? "cie_xyz" : "wavelengths";
  d["bottom_radius_m"] = a.bottom_radius_m;
  d["top_radius_m"] = a.top_radius_m;
  d["ground_albedo"] = spectrum(&AtmosphereParameters::ground_albedo);
  d["sun_irradiance"] = spectrum(&AtmosphereParameters::sun_irradiance);
  d["sun_angular_radius_rad"] = a.sun_angular_radius_rad;
  d["sun_max_zenith_deg"] = a.sun_max_zenith_deg;
  d["rayleigh_scattering"] = spectrum(&AtmosphereParameters::rayleigh_scattering);
  d["mie_scattering"] = spectrum(&AtmosphereParameters::mie_scattering);
  d["mie_extinction"] = spectrum(&AtmosphereParameters::mie_extinction);
  d["mie_phase_g"] = a.mie_phase_g;
  d["absorption_extinction"] = spectrum(&AtmosphereParameters::absorption_extinction);
  return d;
}

}  // namespace

void registerLookups(py::module_& m) {
  m.def("_moon_seen_from", [](const std::array<double, 3>& camera, const std::array<double, 3>& direction,
                              double angular_radius_rad) {
    // The direction and camera as every lookup takes them (lookup_geometry.h).
    const glm::dvec3 dir = lookupDirection({direction[0], direction[1], direction[2]}, "moon_seen_from direction");
    const glm::dvec3 from = lookupPosition({camera[0], camera[1], camera[2]}, "moon_seen_from camera");
    // Beyond a right angle the sine that gives the radius falls again (100
    // deg read as 80) and then turns negative.
    if (!(angular_radius_rad >= 0.0 && angular_radius_rad < kPi / 2.0)) {
      throw Error(ErrorKind::BadInput, "moon_seen_from: angular_radius_rad = " + std::to_string(angular_radius_rad) +
                                           ": must be in [0, pi/2)");
    }
    const Moon moon = Moon::seenFrom(from, dir, angular_radius_rad);
    return py::make_tuple(std::array<double, 3>{moon.centre_m.x, moon.centre_m.y, moon.centre_m.z}, moon.radius_m);
  });
  py::class_<Sky>(m, "Sky")
      .def(py::init([](const std::string& path) { return Sky::load(path); }), py::arg("path"),
           py::call_guard<py::gil_scoped_release>())
      .def("_sky_radiance", [](const Sky& sky, const Rows& camera, const Rows& view, const Rows& sun,
                               const Rows& shadow) { return radianceRows(sky, camera, view, sun, shadow, false); })
      .def("_sky_radiance_eclipse",
           [](const Sky& sky, const Rows& camera, const Rows& view, const Rows& sun, const Rows& moon_centre,
              const Rows& moon_radius) {
             return eclipseRows(sky, camera, view, sun, moon_centre, moon_radius, EclipseLookup::SkyRadiance);
           })
      .def("_irradiance_eclipse",
           [](const Sky& sky, const Rows& point, const Rows& normal, const Rows& sun, const Rows& moon_centre,
              const Rows& moon_radius) {
             return eclipseRows(sky, point, normal, sun, moon_centre, moon_radius, EclipseLookup::Irradiance);
           })
      .def("_radiance_to_point_eclipse",
           [](const Sky& sky, const Rows& camera, const Rows& point, const Rows& sun, const Rows& moon_centre,
              const Rows& moon_radius) {
             return eclipseRows(sky, camera, point, sun, moon_centre, moon_radius, EclipseLookup::RadianceToPoint);
           })
      .def("_radiance_to_point", [](const Sky& sky, const Rows& camera, const Rows& point, const Rows& sun,
                                    const Rows& shadow) { return radianceRows(sky, camera, point, sun, shadow, true); })
      .def("_irradiance",
           [](const Sky& sky, const Rows& point, const Rows& normal, const Rows& sun) {
             const size_t n = rowCount(point, 3, "point_m");
             requireRows(n, {rowCount(normal, 3, "normal"), rowCount(sun, 3, "sun_dir")});
             const double *p = point.data(), *q = normal.data(), *s = sun.data();
             return pair(lookupRows<2>(sky, n, [&](const Sky& group, size_t i) {
               return group.irradiance(row3(p, i), row3(q, i), row3(s, i));
             }));
           })
      .def("_transmittance",
           [](const Sky& sky, const Rows& a, const Rows& b) {
             const size_t n = rowCount(a, 3, "a_m");
             requireRows(n, {rowCount(b, 3, "b_m")});
             const double *pa = a.data(), *pb = b.data();
             return lookupRows<1>(
                 sky, n, [&](const Sky& group, size_t i) { return group.transmittance(row3(pa, i), row3(pb, i)); })[0];
           })
      .def(
          "solar_radiance",
          [](const Sky& sky) {
            return lookupRows<1>(sky, 1, [](const Sky& group, size_t) { return group.solarRadiance(); })[0].reshape(
                {sky.channelCount()});
          },
          "Radiance of the sun disk above the atmosphere, W m^-2 sr^-1 nm^-1, one value per channel.")
      .def_property_readonly("channel_count", &Sky::channelCount)
      .def_property_readonly("orders", &Sky::orders)
      .def_property_readonly("wavelengths_nm", [](const Sky& sky) { return sky.atmosphere().wavelengths_nm; })
      .def_property_readonly(
          "channel_kind",
          [](const Sky& sky) { return sky.channels().kind == ChannelKind::CieXyz ? "cie_xyz" : "wavelengths"; })
      .def_property_readonly("channel_names", [](const Sky& sky) { return sky.channels().names; })
      .def_property_readonly("luminance_weights",
                             [](const Sky& sky) {
                               const std::vector<float>& weights = sky.channelLuminanceWeights();
                               return std::vector<double>(weights.begin(), weights.end());
                             })
      .def_property_readonly("atmosphere", [](const Sky& sky) { return atmosphereDict(sky); })
      .def_property_readonly("bake_report_json", &Sky::bakeReportJson)
      .def_property_readonly("baked_ranges",
                             [](const Sky& sky) {
                               const BakedRanges& r = sky.bakedRanges();
                               py::dict d;
                               d["altitude_min_m"] = r.altitude_min_m;
                               d["altitude_max_m"] = r.altitude_max_m;
                               d["sun_zenith_min_deg"] = r.sun_zenith_min_deg;
                               d["sun_zenith_max_deg"] = r.sun_zenith_max_deg;
                               d["atmosphere_top_m"] = r.atmosphere_top_m;
                               return d;
                             })
      .def_property_readonly("outputs", [](const Sky& sky) {
        py::dict d;
        d["sky_radiance"] = true;
        d["radiance_to_points"] = sky.outputs().radiance_to_points;
        d["ground_irradiance"] = sky.outputs().ground_irradiance;
        return d;
      });
}

}  // namespace skybake::python
