#include "baker/stress/lookup_invariants.h"
#include "data_formats/angles.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "data_formats/parameterization/ray_sphere.h"

namespace skybake {
namespace {

struct Camera {
  const char* name;
  double r_m;  // distance from the planet centre
};

// The camera far out in space; for a planet bigger than this, 10 top radii.
constexpr double kSpaceCameraRadius_m = 1e9;
// Below the ground by this much: the runtime must move it up, not produce NaN.
constexpr double kBelowGroundDepth_m = 1.0;
// Points per ray for the transmittance-along-the-ray checks.
constexpr int kPointsPerRay = 8;
// View zenith angles sampled for the continuity checks, in (0, pi).
constexpr int kContinuityViewAngles = 48;
constexpr int kContinuitySunAngles = 24;
// Half-width of the band around the ground horizon left out of the view
// continuity checks (see continuity()): 10 steps.
constexpr double kHorizonExclusion_rad = 10.0 * kContinuityStep_rad;

std::vector<Camera> cameras(const AtmosphereParameters& a) {
  return {{"ground", a.bottom_radius_m},
          {"mid", 0.5 * (a.bottom_radius_m + a.top_radius_m)},
          {"top", a.top_radius_m},
          {"below_ground", a.bottom_radius_m - kBelowGroundDepth_m},
          {"space", std::max(kSpaceCameraRadius_m, 10.0 * a.top_radius_m)}};
}

// View zenith cosines: the ends, a grid, and the tangent rays.
std::vector<double> viewCosines(const AtmosphereParameters& a, double r) {
  std::vector<double> mus = {-1.0, 1.0};
  constexpr int kGrid = 16;
  for (int i = 0; i < kGrid; ++i) mus.push_back(-1.0 + (2.0 * i + 1.0) / kGrid);
  if (r >= a.bottom_radius_m) mus.push_back(tangentZenithCosine(r, a.bottom_radius_m));
  if (r >= a.top_radius_m) mus.push_back(tangentZenithCosine(r, a.top_radius_m));
  return mus;
}

std::vector<double> sunZenithAngles(const AtmosphereParameters& a) {
  const double lowest = a.sun_max_zenith_deg;
  return {0.0, 60.0, 89.0, 90.0, 91.0, lowest, std::min(lowest + 10.0, 180.0), 180.0};
}

glm::dvec3 direction(double zenith_cosine, double azimuth_rad) {
  return directionFromZenithCosineAzimuth(zenith_cosine, azimuth_rad);
}
glm::dvec3 sunDirection(double zenith_rad) { return directionFromZenithAzimuth(zenith_rad, 0.0); }

// Length of the ray inside the atmosphere from the camera (or, for a ray that
// misses it, a length across it): where the transmittance samples go.
double rayLength(const AtmosphereParameters& a, double r, double mu) {
  const double b = a.bottom_radius_m, t = a.top_radius_m;
  r = std::max(r, b);
  if (rayIntersectsSphere(r, mu, b)) return distanceToInnerSphere(r, mu, b);
  if (r <= t) return distanceToOuterSphere(r, mu, t);
  if (rayIntersectsSphere(r, mu, t)) return -r * mu + safeSqrt(r * r * (mu * mu - 1.0) + t * t);
  return 2.0 * r;
}

class Checks {
 public:
  explicit Checks(const Sky& sky) : sky_(sky), channels_(sky.channelCount()) {}

  void pointQueries() {
    const AtmosphereParameters& a = sky_.atmosphere();
    for (const Camera& cam : cameras(a)) {
      const glm::dvec3 camera(0.0, 0.0, cam.r_m);
      for (double sun_zenith_deg : sunZenithAngles(a)) {
        const glm::dvec3 sun = sunDirection(radiansFromDegrees(sun_zenith_deg));
        const SunAndSkyIrradiance up = sky_.irradiance(camera, {0, 0, 1}, sun);
        const SunAndSkyIrradiance side = sky_.irradiance(camera, {1, 0, 0}, sun);
        const SunAndSkyIrradiance down = sky_.irradiance(camera, {0, 0, -1}, sun);
        const std::string at = fmt::format("irradiance {} sun {} deg", cam.name, sun_zenith_deg);
        for (const SunAndSkyIrradiance& e : {up, side, down}) {
          checkFiniteNonNegative(irradiance_, e.sun, channels_, at + " (sun)");
          checkFiniteNonNegative(irradiance_, e.sky, channels_, at + " (sky)");
        }
        for (double mu : viewCosines(a, cam.r_m)) {
          for (double azimuth_deg : {0.0, 90.0, 180.0}) {
            const glm::dvec3 view = direction(mu, radiansFromDegrees(azimuth_deg));
            ray(cam, camera, mu, view, sun,
                fmt::format("{} mu {:.6f} az {} sun {} deg", cam.name, mu, azimuth_deg, sun_zenith_deg));
          }
        }
      }
    }
  }

  void ray(const Camera& cam, const glm::dvec3& camera, double mu, const glm::dvec3& view, const glm::dvec3& sun,
           const std::string& where) {
    radiance(sky_.skyRadiance(camera, view, sun), "sky " + where);
    radiance(sky_.receivedRadiance(camera, view, sun), "received " + where);
    const double length = rayLength(sky_.atmosphere(), cam.r_m, mu);
    std::vector<Spectrum> along{Spectrum(1.0f)};
    for (int k = 1; k <= kPointsPerRay; ++k) {
      const glm::dvec3 point = camera + view * (length * k / kPointsPerRay);
      radiance(sky_.radianceToPoint(camera, point, sun), fmt::format("to point {}/{} {}", k, kPointsPerRay, where));
      along.push_back(sky_.transmittance(camera, point));
      checkUnitInterval(transmittance_, along.back(), channels_, "segment " + where);
      ++lookups_;
    }
    checkNonIncreasing(monotone_, along, channels_, where);
  }

  void radiance(const RadianceAndTransmittance& value, const std::string& where) {
    ++lookups_;
    checkFiniteNonNegative(radiance_, value.radiance, channels_, where);
    checkUnitInterval(transmittance_, value.transmittance, channels_, where);
    for (int c = 0; c < channels_; ++c) {
      if (!std::isfinite(value.radiance[c])) continue;
      min_ = std::min(min_, double(value.radiance[c]));
      max_ = std::max(max_, double(value.radiance[c]));
    }
  }

  // Pairs of lookups kContinuityStep_rad apart in view zenith, then in sun
  // zenith, from the cameras inside the atmosphere.
  void continuity() {
    const AtmosphereParameters& a = sky_.atmosphere();
    const double floor = kContinuityFloorShare * max_;
    const double lowest_sun_rad = radiansFromDegrees(a.sun_max_zenith_deg);
    for (const Camera& cam : cameras(a)) {
      if (cam.r_m < a.bottom_radius_m || cam.r_m > a.top_radius_m) continue;
      const glm::dvec3 camera(0.0, 0.0, cam.r_m);
      const double horizon_mu = tangentZenithCosine(cam.r_m, a.bottom_radius_m);
      const double horizon_zenith = std::acos(horizon_mu);
      for (int si = 0; si < kContinuitySunAngles; ++si) {
        const double sun_zenith = lowest_sun_rad * (si + 0.5) / kContinuitySunAngles;
        const glm::dvec3 sun = sunDirection(sun_zenith);
        const glm::dvec3 sun_before = sunDirection(sun_zenith - kContinuityStep_rad);
        const glm::dvec3 sun_moved = sunDirection(sun_zenith + kContinuityStep_rad);
        // No pair within kHorizonExclusion_rad of the ground horizon: there
        // the ray's length through the densest air has a square-root
        // singularity in the view angle (1e-4 rad below the horizon from
        // 30 km already cuts ~28 km out of the tangent path) and, across it,
        // the ground occludes the atmosphere behind the tangent point.
        std::vector<double> zeniths;
        for (int vi = 0; vi < kContinuityViewAngles; ++vi) {
          const double zenith = kPi * (vi + 0.5) / kContinuityViewAngles;
          if (std::abs(zenith - horizon_zenith) > kHorizonExclusion_rad) zeniths.push_back(zenith);
        }
        // and the pairs just outside that band, where the mu axis is densest.
        zeniths.push_back(horizon_zenith - 2.0 * kHorizonExclusion_rad);
        zeniths.push_back(horizon_zenith + 2.0 * kHorizonExclusion_rad);
        for (double zenith : zeniths) {
          for (double azimuth : {0.0, 0.5 * kPi, kPi}) {
            const glm::dvec3 view = direction(std::cos(zenith), azimuth);
            const glm::dvec3 view_before = direction(std::cos(zenith - kContinuityStep_rad), azimuth);
            const glm::dvec3 view_moved = direction(std::cos(zenith + kContinuityStep_rad), azimuth);
            const std::string where = fmt::format("{} view zenith {:.5f} rad az {:.2f} sun zenith {:.4f} rad", cam.name,
                                                  zenith, azimuth, sun_zenith);
            const RadianceAndTransmittance sky = sky_.skyRadiance(camera, view, sun);
            checkContinuous(view_continuity_, sky_.skyRadiance(camera, view_before, sun).radiance, sky.radiance,
                            sky_.skyRadiance(camera, view_moved, sun).radiance, floor, channels_, "sky " + where);
            checkContinuous(sun_continuity_, sky_.skyRadiance(camera, view, sun_before).radiance, sky.radiance,
                            sky_.skyRadiance(camera, view, sun_moved).radiance, floor, channels_, "sky " + where);
            const RadianceAndTransmittance received = sky_.receivedRadiance(camera, view, sun);
            checkContinuous(view_continuity_, sky_.receivedRadiance(camera, view_before, sun).radiance,
                            received.radiance, sky_.receivedRadiance(camera, view_moved, sun).radiance, floor,
                            channels_, "received " + where);
            checkContinuous(sun_continuity_, sky_.receivedRadiance(camera, view, sun_before).radiance,
                            received.radiance, sky_.receivedRadiance(camera, view, sun_moved).radiance, floor,
                            channels_, "received " + where);
            lookups_ += 10;
          }
        }
      }
    }
  }

  LookupInvariants result() const {
    LookupInvariants out;
    out.invariants = {radiance_, irradiance_, transmittance_, monotone_, view_continuity_, sun_continuity_};
    out.lookups = lookups_;
    out.min_radiance = min_;
    out.max_radiance = max_;
    return out;
  }

 private:
  const Sky& sky_;
  int channels_;
  InvariantResult radiance_{"lookup radiance finite >= 0"};
  InvariantResult irradiance_{"lookup irradiance finite >= 0"};
  InvariantResult transmittance_{"lookup transmittance in [0,1]"};
  InvariantResult monotone_{"transmittance non-increasing along rays"};
  InvariantResult view_continuity_{"continuous in view angle"};
  InvariantResult sun_continuity_{"continuous in sun angle"};
  long long lookups_ = 0;
  double min_ = std::numeric_limits<double>::infinity();
  double max_ = 0.0;
};

}  // namespace

LookupInvariants checkLookupInvariants(const Sky& sky) {
  Checks checks(sky);
  checks.pointQueries();
  checks.continuity();
  return checks.result();
}

}  // namespace skybake
