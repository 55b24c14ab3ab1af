#include "baker/validation/validation.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "baker/reference/reference_solver.h"
#include "baker/validation/validation_queries.h"
#include "data_formats/error.h"
#include "data_formats/queries/local_frame.h"
#include "runtime/colour/spectral_to_xyz.h"
#include "runtime/physics/atmosphere_ray.h"

namespace skybake {
namespace {

enum class RayKind { Sky, Ground, ToPoint, Misses };

RayKind rayKind(const AtmosphereParameters& a, const RadianceQuery& q) {
  const QueryGeometry g = geometryOf(a, q);
  const AtmosphereRay ray = atmosphereRay(a.bottom_radius_m, a.top_radius_m, g.camera, g.view, q.distance_m);
  if (!ray.inside) return RayKind::Misses;
  if (q.distance_m > 0.0) return RayKind::ToPoint;
  return ray.ends_on_ground ? RayKind::Ground : RayKind::Sky;
}

}  // namespace

std::string radianceQuantity(const AtmosphereParameters& a, const RadianceQuery& q) {
  switch (rayKind(a, q)) {
    case RayKind::Sky:
      return "sky_radiance";
    case RayKind::Ground:
      return "ground_radiance";
    case RayKind::ToPoint:
      return "radiance_to_point";
    case RayKind::Misses:
      break;
  }
  return "";
}

namespace {

// Queries with the sun below the camera's horizon are sampled partly toward
// sunlit air (referenceSamplesTowardLitAir): their keys name that sampling,
// so values cached before it (other seeds, more noise) are never mistaken
// for them, while the daylight keys, and values, stay as they were. The 2
// marks the sampling that guides the ground's reflection and the sky
// irradiance's first direction as well; values keyed " guided" came from
// the one before it, which drew those directions by the cosine alone.
std::string samplingSuffix(double sun_zenith_deg) {
  return referenceSamplesTowardLitAir(directionFromZenithAzimuthDeg(sun_zenith_deg, 0.0).z) ? " guided2" : "";
}

// An eclipse's value is not the plain sky's: its key names the moon.
std::string withMoon(const std::string& key, const MoonQuery& moon) {
  return moon.present() ? fmt::format("{} moon {} {}", key, moon.separation_deg, moon.angular_radius_deg) : key;
}

// The query's moon seen from the camera: turned from the sun toward +y,
// perpendicular to the sun's x-z plane. None for a query without one.
Moon moonOf(const glm::dvec3& camera, const glm::dvec3& sun, const MoonQuery& q) {
  if (!q.present()) return Moon{};
  const double s = radiansFromDegrees(q.separation_deg);
  const glm::dvec3 moon_dir = sun * std::cos(s) + glm::dvec3(0.0, 1.0, 0.0) * std::sin(s);
  return Moon::seenFrom(camera, glm::normalize(moon_dir), radiansFromDegrees(q.angular_radius_deg));
}

}  // namespace

int referencePathsFor(const RadianceQuery& q, int paths) {
  const bool twilight_point =
      q.distance_m > 0.0 && referenceSamplesTowardLitAir(directionFromZenithAzimuthDeg(q.sun_zenith_deg, 0.0).z);
  return twilight_point ? paths * kTwilightPointRayPathFactor : paths;
}

int referencePathsFor(const QuerySet& queries, size_t item, int paths) {
  return item < queries.radiance.size() ? referencePathsFor(queries.radiance[item], paths) : paths;
}

std::string radianceKey(const RadianceQuery& q) {
  // A query given more paths than the set's names the factor, so its value
  // is never mistaken for one from fewer.
  const int path_factor = referencePathsFor(q, 1);
  const std::string more_paths = path_factor > 1 ? fmt::format(" paths x{}", path_factor) : std::string();
  return withMoon(fmt::format("r {} {} {} {} {}{}{}", q.altitude_m, q.sun_zenith_deg, q.view_zenith_deg,
                              q.view_azimuth_deg, q.distance_m, samplingSuffix(q.sun_zenith_deg), more_paths),
                  q.moon);
}

std::string irradianceKey(const IrradianceQuery& q) {
  return withMoon(fmt::format("e {} {}{}", q.altitude_m, q.sun_zenith_deg, samplingSuffix(q.sun_zenith_deg)), q.moon);
}

QueryGeometry geometryOf(const AtmosphereParameters& a, const RadianceQuery& q) {
  QueryGeometry g{cameraAtAltitude(a.bottom_radius_m, q.altitude_m),
                  directionFromZenithAzimuthDeg(q.view_zenith_deg, q.view_azimuth_deg),
                  directionFromZenithAzimuthDeg(q.sun_zenith_deg, 0.0), Moon{}};
  g.moon = moonOf(g.camera, g.sun, q.moon);
  return g;
}

QueryGeometry geometryOf(const AtmosphereParameters& a, const IrradianceQuery& q) {
  QueryGeometry g{cameraAtAltitude(a.bottom_radius_m, q.altitude_m), glm::dvec3(0.0, 0.0, 1.0),
                  directionFromZenithAzimuthDeg(q.sun_zenith_deg, 0.0), Moon{}};
  g.moon = moonOf(g.camera, g.sun, q.moon);
  return g;
}

ReferenceSettings referenceSettings(int paths, const std::string& cache_dir, bool no_cache) {
  ReferenceSettings settings;
  settings.paths = paths;
  settings.cache_directory = no_cache            ? std::filesystem::path()
                             : cache_dir.empty() ? defaultReferenceCacheDirectory()
                                                 : std::filesystem::path(cache_dir);
  // Found now, not after the reference has been computed and cannot be kept.
  std::error_code error;
  if (!settings.cache_directory.empty() && std::filesystem::exists(settings.cache_directory, error) &&
      !std::filesystem::is_directory(settings.cache_directory, error)) {
    throwBadInput(fmt::format("{}: the reference cache directory is a file", settings.cache_directory.string()));
  }
  return settings;
}

std::vector<size_t> queriesMissingFromCache(const ReferenceCache& cache, const QuerySet& queries) {
  std::vector<size_t> missing;
  for (size_t i = 0; i < queries.radiance.size(); ++i) {
    if (!cache.find(radianceKey(queries.radiance[i]))) missing.push_back(i);
  }
  for (size_t i = 0; i < queries.irradiance.size(); ++i) {
    if (!cache.find(irradianceKey(queries.irradiance[i]))) missing.push_back(queries.radiance.size() + i);
  }
  return missing;
}

double computeInCheckpointedBatches(const std::vector<size_t>& items, const std::string& stage, ProgressSink& progress,
                                    ReferenceCache& cache, const std::function<void(size_t)>& compute,
                                    const std::function<void(size_t)>& store) {
  const auto start = std::chrono::steady_clock::now();
  auto last_checkpoint = start;
  progress.beginStage(stage, items.size());
  // In batches, so that what is done is saved to the cache at least every
  // kReferenceCheckpointSeconds. Each query has its own seed (a hash of the
  // query), so results depend neither on the order, the batches nor the
  // thread that computes them.
  const size_t batch = std::max<size_t>(kReferenceQueriesPerThreadPerBatch * omp_get_max_threads(), 1);
  for (size_t first = 0; first < items.size(); first += batch) {
    const size_t last = std::min(first + batch, items.size());
#pragma omp parallel for schedule(dynamic)
    for (size_t k = first; k < last; ++k) {
      compute(items[k]);
      progress.advance(1);
    }
    for (size_t k = first; k < last; ++k) store(items[k]);
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last_checkpoint).count() >= kReferenceCheckpointSeconds) {
      cache.saveChunkIfWritable();
      last_checkpoint = now;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.endStage(seconds);
  cache.saveChunkIfWritable();
  for (const std::string& note : cache.notes()) progress.note(note);
  return seconds;
}

ReferenceValues computeReferenceValues(const AtmosphereParameters& a, const QuerySet& queries,
                                       const ReferenceSettings& settings, ProgressSink& progress,
                                       const std::string& stage) {
  ReferenceCache cache(settings.cache_directory, a, settings.paths);
  const ReferenceSolver solver(a);
  ReferenceValues out;
  out.radiance.resize(queries.radiance.size());
  out.irradiance.resize(queries.irradiance.size());
  const std::vector<size_t> missing = queriesMissingFromCache(cache, queries);
  for (size_t i = 0; i < queries.radiance.size(); ++i) {
    if (auto hit = cache.find(radianceKey(queries.radiance[i]))) out.radiance[i] = *hit;
  }
  for (size_t i = 0; i < queries.irradiance.size(); ++i) {
    if (auto hit = cache.find(irradianceKey(queries.irradiance[i]))) out.irradiance[i] = *hit;
  }
  out.cached = static_cast<int>(queries.radiance.size() + queries.irradiance.size() - missing.size());
  auto compute = [&](size_t item) {
    if (item < queries.radiance.size()) {
      const RadianceQuery& q = queries.radiance[item];
      const QueryGeometry g = geometryOf(a, q);
      const ReferenceRay ray{g.camera, g.view, g.sun, q.distance_m};
      const ReferenceEstimate e =
          solver.radiance(ray, referencePathsFor(q, settings.paths), stableHash(radianceKey(q)), g.moon);
      out.radiance[item] = {e.value, e.standard_error, solver.transmittance(ray)};
    } else {
      const IrradianceQuery& q = queries.irradiance[item - queries.radiance.size()];
      const QueryGeometry g = geometryOf(a, q);
      const ReferenceEstimate e =
          solver.skyIrradiance(g.camera, g.sun, settings.paths, stableHash(irradianceKey(q)), g.moon);
      out.irradiance[item - queries.radiance.size()] = {e.value, e.standard_error, SpectrumD(1.0)};
    }
  };
  auto storeInCache = [&](size_t item) {
    if (item < queries.radiance.size()) {
      cache.store(radianceKey(queries.radiance[item]), out.radiance[item]);
    } else {
      const size_t i = item - queries.radiance.size();
      cache.store(irradianceKey(queries.irradiance[i]), out.irradiance[i]);
    }
  };
  out.seconds = computeInCheckpointedBatches(missing, stage, progress, cache, compute, storeInCache);
  out.computed = static_cast<int>(missing.size());
  return out;
}

QuerySet queryPiece(const QuerySet& queries, int piece, int pieces) {
  QuerySet out{queries.name, {}, {}};
  size_t item = 0;
  for (const RadianceQuery& q : queries.radiance) {
    if (static_cast<int>(item++ % pieces) == piece - 1) out.radiance.push_back(q);
  }
  for (const IrradianceQuery& q : queries.irradiance) {
    if (static_cast<int>(item++ % pieces) == piece - 1) out.irradiance.push_back(q);
  }
  return out;
}

MethodValues evaluateBake(const Sky& sky, const QuerySet& queries) {
  const AtmosphereParameters& a = sky.atmosphere();
  MethodValues out;
  const auto start = std::chrono::steady_clock::now();
  for (const RadianceQuery& q : queries.radiance) {
    const QueryGeometry g = geometryOf(a, q);
    const glm::dvec3 point = g.camera + g.view * q.distance_m;
    // A query without a moon has one of radius 0: the uneclipsed lookups.
    const Sunlight sun{g.sun, g.moon};
    const RadianceAndTransmittance v =
        q.distance_m > 0.0 ? sky.radianceToPoint(g.camera, point, sun) : sky.receivedRadiance(g.camera, g.view, sun);
    out.radiance.push_back(v.radiance);
    out.transmittance.push_back(v.transmittance);
  }
  out.seconds_per_ray = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
                        std::max<size_t>(queries.radiance.size(), 1);
  for (const IrradianceQuery& q : queries.irradiance) {
    const QueryGeometry g = geometryOf(a, q);
    out.irradiance.push_back(sky.irradiance(g.camera, g.view, {g.sun, g.moon}).sky);
  }
  return out;
}

QuerySet queriesAnsweredBy(const Sky& sky, const QuerySet& queries, std::string& left_out) {
  const AtmosphereParameters& a = sky.atmosphere();
  const SceneOutputs& outputs = sky.outputs();
  const BakedRanges& ranges = sky.bakedRanges();
  QuerySet out{queries.name, {}, {}};
  size_t to_points = 0, to_ground = 0, outside = 0;
  for (const RadianceQuery& q : queries.radiance) {
    if (q.distance_m > 0.0 && !outputs.radiance_to_points) {
      ++to_points;
      continue;
    }
    const QueryGeometry g = geometryOf(a, q);
    const double point_altitude_m =
        q.distance_m > 0.0 ? glm::length(g.camera + g.view * q.distance_m) - a.bottom_radius_m : q.altitude_m;
    // Ranges count altitudes below the ground as the ground (where a camera
    // below it is looked up); a point below it is outside them all the same.
    const bool point_below_ground = q.distance_m > 0.0 && point_altitude_m < -kPointOnGroundTolerance_m;
    if (!ranges.contains(q.altitude_m, q.sun_zenith_deg) || !ranges.containsAltitude(point_altitude_m) ||
        point_below_ground) {
      ++outside;
      continue;
    }
    if (q.distance_m <= 0.0 && !outputs.ground_irradiance &&
        atmosphereRay(a.bottom_radius_m, a.top_radius_m, g.camera, g.view, 0.0).ends_on_ground) {
      ++to_ground;
      continue;
    }
    out.radiance.push_back(q);
  }
  if (outputs.ground_irradiance) out.irradiance = queries.irradiance;
  std::vector<std::string> parts;
  if (to_points > 0) parts.push_back(fmt::format("{} radiance-to-point queries (no radiance_to_points)", to_points));
  if (to_ground > 0) parts.push_back(fmt::format("{} ground-ray queries (no ground_irradiance)", to_ground));
  if (!outputs.ground_irradiance && !queries.irradiance.empty()) {
    parts.push_back(fmt::format("{} irradiance queries (no ground_irradiance)", queries.irradiance.size()));
  }
  left_out.clear();
  for (size_t i = 0; i < parts.size(); ++i) left_out += (i > 0 ? ", " : "") + parts[i];
  if (!left_out.empty()) left_out = "not validated, left out of the bake by its scene.outputs: " + left_out;
  if (outside > 0) {
    left_out += fmt::format(
        "{}not validated, outside the bake's scene ranges (altitude {:g} to {:g} m, sun zenith "
        "{:g} to {:g} deg; for a point, both ends): {} radiance queries",
        left_out.empty() ? "" : "\n", ranges.altitude_min_m, ranges.altitude_max_m, ranges.sun_zenith_min_deg,
        ranges.sun_zenith_max_deg, outside);
  }
  return out;
}

ErrorReport compareWithReference(const AtmosphereParameters& a, const QuerySet& queries,
                                 const ReferenceValues& reference, const MethodValues& method, int reference_paths) {
  ErrorReport report;
  report.query_set = queries.name;
  report.wavelengths_nm = a.wavelengths_nm;
  report.channel_names = channelNames(a);
  report.reference_paths = reference_paths;
  const int channels = a.channelCount();
  // A colour bake's reference (colour_reference.h) is radiance and
  // irradiance in X, Y, Z only: it has no transmittance to compare with.
  const bool compare_transmittance = !a.storesCieXyz();
  // X, Y, Z integrate spectral radiance over the colour-matching functions,
  // each of which integrates to the same width (equal-energy white): the
  // spectral threshold times that width leaves out the same dark queries.
  const double value_scale = a.storesCieXyz() ? colour::ybarIntegral_nm() : 1.0;
  report.smallest_compared_value = kSmallestComparedValue * value_scale;
  const std::vector<CameraAltitudeGroup> groups = cameraAltitudeGroups(queries);
  ErrorStatsBuilder stats;
  for (size_t i = 0; i < queries.radiance.size(); ++i) {
    const RadianceQuery& q = queries.radiance[i];
    const std::string quantity = radianceQuantity(a, q);
    if (quantity.empty()) continue;
    const SunBand sun_band = sunBand(q.sun_zenith_deg);
    const char* band = sunBandName(sun_band);
    const CachedReference& r = reference.radiance[i];
    const size_t group = cameraAltitudeGroupOf(groups, q.altitude_m);
    for (int c = 0; c < channels; ++c) {
      stats.add(quantity, band, group, c, method.radiance[i][c], r.value[c], r.standard_error[c],
                smallestComparedValue(sun_band) * value_scale);
      if (compare_transmittance) {
        stats.add("transmittance", "all", std::nullopt, c, method.transmittance[i][c], r.transmittance[c], 0.0,
                  kSmallestComparedValue);
      }
    }
  }
  if (!method.irradiance.empty()) {
    for (size_t i = 0; i < queries.irradiance.size(); ++i) {
      const SunBand sun_band = sunBand(queries.irradiance[i].sun_zenith_deg);
      const char* band = sunBandName(sun_band);
      const size_t group = cameraAltitudeGroupOf(groups, queries.irradiance[i].altitude_m);
      for (int c = 0; c < channels; ++c) {
        stats.add("sky_irradiance", band, group, c, method.irradiance[i][c], reference.irradiance[i].value[c],
                  reference.irradiance[i].standard_error[c], smallestComparedValue(sun_band) * value_scale);
      }
    }
  }
  report.rows = stats.rows(channels, groups, false);
  report.altitude_rows = stats.rows(channels, groups, true);
  return report;
}

}  // namespace skybake
