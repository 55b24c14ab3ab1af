#include "baker/render/sun_disk_pixels.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "runtime/physics/atmosphere_ray.h"
#include "runtime/physics/moon_occluder.h"

namespace skybake {
namespace {

// Subsamples across the sun's angular radius. Each subsample counts the disk
// with a linear ramp one subsample wide across its edge (antialiased), so
// the covered area converges as the square of the spacing instead of
// jumping as subsamples cross the edge: at 8 per radius the disk's area in
// a pixel is right to about 0.1 %.
constexpr double kSubsamplesPerSunRadius = 8.0;

// Most subsamples along a pixel's side. Bounds the work where pixels are
// far larger than the sun (a 64-pixel-wide map's pixels are 21 sun radii
// across on Earth: about 240 subsamples a side at the rate above, counting
// the pixel's diagonal); beyond it the ramp widens with the spacing, and the
// correction below keeps the ramped disk's area the sun's.
constexpr int kMaxSubsamplesPerPixelSide = 256;

// A pixel is searched for the disk when its centre lies within the disk's
// radius plus this many times the pixel's own angular reach (the farthest
// of its corners and edge midpoints from its centre). A pixel's edges bulge
// between those points by far less than half the reach in every
// projection, so no covered pixel is skipped; a searched pixel that the
// disk misses only costs its subsamples.
constexpr double kPixelReachMargin = 1.5;

// The angle between two directions, precise at the sun's small angles.
constexpr auto& angleBetween = kernel::skybakeAngleBetween;

// How far from its centre's direction pixel (x, y) reaches, radians.
double pixelReach_rad(const SkyView& v, int x, int y, const glm::dvec3& centre) {
  double reach = 0.0;
  for (double dy : {0.0, 0.5, 1.0}) {
    for (double dx : {0.0, 0.5, 1.0}) {
      glm::dvec3 dir;
      if (directionAtImagePoint(v, x + dx, y + dy, dir)) reach = std::max(reach, angleBetween(centre, dir));
    }
  }
  return reach;
}

}  // namespace

void addSunDisk(const Sky& sky, const SkyView& v, SpectralImage& image) {
  const double radius = sky.atmosphere().sun_angular_radius_rad;
  if (!v.sun_disk || radius <= 0.0) return;
  const Spectrum solar = sky.solarRadiance();
  const glm::dvec3 camera = cameraPosition(sky, v);
  const glm::dvec3 sun = sunDirection(v);
  const double bottom = sky.atmosphere().bottom_radius_m;
  const double top = sky.atmosphere().top_radius_m;
  const double target_spacing = radius / kSubsamplesPerSunRadius;
  // The moon before the sun, seen from the camera (none: nothing hidden).
  const glm::dvec3 to_moon = v.moon.centre_m - camera;
  const double moon_distance = glm::length(to_moon);
  const bool moon = v.moon.present() && moon_distance > v.moon.radius_m;
  const glm::dvec3 moon_dir = moon ? to_moon / moon_distance : glm::dvec3(0.0, 0.0, 1.0);
  const double moon_radius = moon ? std::asin(v.moon.radius_m / moon_distance) : 0.0;
  // The disk's solid angle the subsamples count with and without the moon
  // (transmittance aside), to scale the image's sun to the exact visible
  // part of the disk (Moon::visibleSunFraction): the limbs' ramps blur
  // where the moon's and the sun's edges lie closer than a ramp, and would
  // leave a sliver of sun in totality.
  double counted_past_moon = 0.0, counted_whole = 0.0;
  std::vector<Spectrum> added_sun(moon ? static_cast<size_t>(v.width) * v.height : 0, Spectrum(0.0f));
#pragma omp parallel for schedule(dynamic) reduction(+ : counted_past_moon, counted_whole)
  for (int y = 0; y < v.height; ++y) {
    for (int x = 0; x < v.width; ++x) {
      glm::dvec3 centre;
      if (!directionAtImagePoint(v, x + 0.5, y + 0.5, centre)) continue;
      const double reach = pixelReach_rad(v, x, y, centre);
      if (angleBetween(centre, sun) > radius + kPixelReachMargin * reach) continue;
      const int n =
          std::clamp(static_cast<int>(std::ceil(2.0 * reach / target_spacing)), 1, kMaxSubsamplesPerPixelSide);
      const double ramp = std::max(target_spacing, 2.0 * reach / n);
      // The ramp adds ramp^2 / 12 to the disk's squared radius (to second
      // order, the disk being nearly flat): count it from a radius that
      // much smaller, so the ramped disk has the sun's area.
      const double ramp_radius = std::sqrt(std::max(radius * radius - ramp * ramp / 12.0, 0.0));
      double pixel_solid_angle = 0.0;
      Spectrum sun_solid_angle(0.0f);  // covered solid angle times transmittance, per channel
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
          const double sx = x + (i + 0.5) / n, sy = y + (j + 0.5) / n;
          glm::dvec3 dir;
          if (!directionAtImagePoint(v, sx, sy, dir)) continue;
          const double solid_angle = solidAnglePerPixelArea_sr(v, sx, sy);
          pixel_solid_angle += solid_angle;
          // The moon's limb gets the same ramp as the sun's, from outside.
          const double past_moon =
              moon ? std::clamp(0.5 + (angleBetween(dir, moon_dir) - moon_radius) / ramp, 0.0, 1.0) : 1.0;
          const double covered_whole = std::clamp(0.5 + (ramp_radius - angleBetween(dir, sun)) / ramp, 0.0, 1.0);
          const double covered = covered_whole * past_moon;
          counted_whole += covered_whole * solid_angle;
          counted_past_moon += covered * solid_angle;
          if (covered <= 0.0) continue;
          const AtmosphereRay ray = atmosphereRay(bottom, top, camera, dir, 0.0);
          if (ray.ends_on_ground) continue;
          const Spectrum transmittance =
              ray.inside ? glm::exp(-sky.sampler().opticalDepthToTop(sky.tables().optical_depth, ray.r, ray.mu))
                         : Spectrum(1.0f);
          sun_solid_angle += transmittance * static_cast<float>(covered * solid_angle);
        }
      }
      if (!(pixel_solid_angle > 0.0)) continue;
      const Spectrum added = solar * sun_solid_angle / static_cast<float>(pixel_solid_angle);
      if (moon) {
        added_sun[static_cast<size_t>(y) * v.width + x] = added;
        continue;
      }
      float* pixel = image.pixel(x, y);
      for (int c = 0; c < image.channels; ++c) pixel[c] += added[c];
    }
  }
  if (!moon) return;
  const double exact = v.moon.visibleSunFraction(camera, sun, radius);
  const float scale = counted_past_moon > 0.0 ? static_cast<float>(exact * counted_whole / counted_past_moon) : 0.0f;
  for (int y = 0; y < v.height; ++y) {
    for (int x = 0; x < v.width; ++x) {
      const Spectrum added = added_sun[static_cast<size_t>(y) * v.width + x] * scale;
      float* pixel = image.pixel(x, y);
      for (int c = 0; c < image.channels; ++c) pixel[c] += added[c];
    }
  }
}

}  // namespace skybake
