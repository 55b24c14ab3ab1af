// The sky during a solar eclipse (docs/ECLIPSES.md). Single scattering is
// what the uneclipsed lookup gives, scaled per channel by the ratio of two
// integrals along the view ray, with and without the moon hiding part of
// the sun at each point (so the tables' accuracy is kept, the moon's shadow
// is followed exactly, and a moon far from the sun changes nothing).
// Multiple scattering and the sky's irradiance are scaled by the sun's
// visible fraction averaged over the neighbourhood (eclipse_skylight.h).
#include <algorithm>

#include <glm/geometric.hpp>

#include "runtime/lookup_geometry.h"
#include "runtime/physics/eclipse_skylight.h"
#include "runtime/sky.h"
#include "runtime/sky_lookup_constants.h"
#include "runtime/sky_lookup_start.h"

namespace skybake {
namespace {

Spectrum eclipsedShare(const Spectrum& eclipsed, const Spectrum& plain) {
  Spectrum share(0.0f);
  for (int c = 0; c < kMaxChannels; ++c) {
    share[c] = plain[c] > kEclipseSmallestUneclipsedSingle ? std::clamp(eclipsed[c] / plain[c], 0.0f, 1.0f) : 0.0f;
  }
  return share;
}

}  // namespace

bool Sky::moonHidesSunNear(const glm::dvec3& point, const glm::dvec3& sun_dir, const Moon& moon) const {
  if (!moon.present()) return false;
  const glm::dvec3 to_moon = moon.centre_m - point;
  const double distance = glm::length(to_moon);
  const double top = sampler_.domain().top_radius_m, bottom = sampler_.domain().bottom_radius_m;
  // Anywhere in the atmosphere lies within this of the point, and the moon
  // is seen from there displaced by at most this over its distance.
  const double reach_m = 2.0 * std::sqrt(top * top - bottom * bottom) + (glm::length(point) - bottom);
  if (!(distance > reach_m + moon.radius_m)) return true;
  const double parallax_rad = reach_m / (distance - reach_m);
  const double moon_radius_rad = std::asin(std::min(moon.radius_m / (distance - reach_m), 1.0));
  const double separation_rad = std::atan2(glm::length(glm::cross(to_moon, sun_dir)), glm::dot(to_moon, sun_dir));
  return separation_rad < atmosphere().sun_angular_radius_rad + moon_radius_rad + parallax_rad;
}

bool Sky::eclipsed(const Sunlight& sun) {
  requireLookupMoon(sun.moon);
  return sun.moon.present();
}

Spectrum Sky::eclipseSkylight(const glm::dvec3& point_given, const Sunlight& sun) const {
  const glm::dvec3 point = lookupPosition(point_given, "point");
  const glm::dvec3 sun_dir = lookupDirection(sun.direction, "sun direction");
  requireLookupMoon(sun.moon);
  requireOneLaneGroup("eclipseSkylight");
  // The kernel's points lie within the atmosphere's reach of `point`: a moon
  // that hides the sun from none of them leaves F exactly 1.
  if (!moonHidesSunNear(point, sun_dir, sun.moon)) return Spectrum(1.0f);
  return eclipseSkylightFraction(atmosphere(), sun.moon, point, sun_dir);
}

RadianceAndTransmittance Sky::eclipsedSkyRadiance(const glm::dvec3& camera_given, const glm::dvec3& view_dir_given,
                                                  const Sunlight& sun, double shadow_length_m) const {
  const auto [camera, view_dir, sun_dir] = checkedView(camera_given, view_dir_given, sun.direction);
  const Moon& moon = sun.moon;
  if (insideMoon(camera, moon)) return {Spectrum(0.0f), Spectrum(0.0f)};
  SkyRadianceParts p = skyRadianceParts(camera, view_dir, sun_dir, shadow_length_m);
  if (!p.inside) return {Spectrum(0.0f), Spectrum(1.0f)};
  if (moonHidesSunNear(p.start.origin, sun_dir, moon)) {
    const AtmosphereRay& s = p.start;
    const SunlitRay ray{s.r, s.mu, p.mu_s, p.nu, s.ends_on_ground};
    const MoonAlongRay along{moon, s.origin, s.dir, sun_dir, atmosphere().sun_angular_radius_rad};
    const SingleScattering with_moon =
        integratedSingleScattering(ray, p.lit_from_m, s.length, kEclipseSingleScatteringSegments, &along);
    const SingleScattering without =
        integratedSingleScattering(ray, p.lit_from_m, s.length, kEclipseSingleScatteringSegments);
    p.single.rayleigh *= eclipsedShare(with_moon.rayleigh, without.rayleigh);
    p.single.mie *= eclipsedShare(with_moon.mie, without.mie);
  }
  // The skylight share where the ray starts in the atmosphere.
  p.multiple *= sun.camera_skylight ? *sun.camera_skylight : eclipseSkylight(p.start.origin, {sun_dir, moon});
  return {p.single.rayleigh * static_cast<float>(rayleighPhase(p.nu)) +
              p.single.mie * static_cast<float>(mie_phase_(p.nu)) + p.multiple,
          p.transmittance};
}

SunAndSkyIrradiance Sky::eclipsedIrradiance(const glm::dvec3& point_given, const glm::dvec3& normal_given,
                                            const Sunlight& sun) const {
  const auto [point, normal, sun_dir] = checkedSurface(point_given, normal_given, sun.direction);
  SunAndSkyIrradiance e = irradiance(point, normal, sun_dir);
  const double visible = sun.moon.visibleSunFraction(point, sun_dir, atmosphere().sun_angular_radius_rad);
  e.sun *= static_cast<float>(visible);
  if (moonHidesSunNear(point, sun_dir, sun.moon)) e.sky *= eclipsedSkyIrradianceShare(point, sun_dir, sun.moon);
  return e;
}

RadianceAndTransmittance Sky::eclipsedRadianceToPoint(const glm::dvec3& camera_given, const glm::dvec3& point_given,
                                                      const Sunlight& sun, double shadow_length_m_given) const {
  const glm::dvec3 camera = lookupPosition(camera_given, "camera");
  const glm::dvec3 point = lookupPosition(point_given, "point");
  const glm::dvec3 sun_dir = lookupDirection(sun.direction, "sun direction");
  const double shadow_length_m = lookupShadowLength(shadow_length_m_given);
  const Moon& moon = sun.moon;
  if (insideMoon(camera, moon)) return {Spectrum(0.0f), Spectrum(0.0f)};
  RadianceAndTransmittance v = radianceToPoint(camera, point, sun_dir, shadow_length_m);
  const glm::dvec3 offset = point - camera;
  const double distance = glm::length(offset);
  if (!(distance > 0.0)) return v;
  const glm::dvec3 view_dir = offset / distance;
  const AtmosphereRay s = enterAtmosphere(sampler_.domain(), camera, view_dir);
  // The segment's lit part, as the plain lookup takes it: from its start in
  // the atmosphere to the shadow of scene geometry before the point.
  const double d = std::min(distance - s.moved, s.length) - std::max(shadow_length_m - s.moved, 0.0);
  if (!s.inside || d <= 0.0 || !moonHidesSunNear(s.origin, sun_dir, moon)) return v;
  const double mu_s = clampCosine(glm::dot(s.origin, sun_dir) / s.r);
  const double nu = clampCosine(glm::dot(view_dir, sun_dir));
  const SunlitRay ray{s.r, s.mu, mu_s, nu, s.ends_on_ground};
  const MoonAlongRay along{moon, s.origin, s.dir, sun_dir, atmosphere().sun_angular_radius_rad};
  const SingleScattering with_moon = integratedSingleScattering(ray, 0.0, d, kEclipseSingleScatteringSegments, &along);
  const SingleScattering without = integratedSingleScattering(ray, 0.0, d, kEclipseSingleScatteringSegments);
  auto withPhases = [&](const SingleScattering& x) {
    return x.rayleigh * static_cast<float>(rayleighPhase(nu)) + x.mie * static_cast<float>(mie_phase_(nu));
  };
  // The plain radiance less its single scattering (the integral's, which
  // the segment's own lookup matches to its accuracy) is what the tables
  // scattered more than once.
  const Spectrum multiple = glm::max(v.radiance - withPhases(without), Spectrum(0.0f));
  const Spectrum skylight = sun.camera_skylight ? *sun.camera_skylight : eclipseSkylight(s.origin, {sun_dir, moon});
  v.radiance = multiple * skylight + withPhases(with_moon);
  return v;
}

Spectrum Sky::eclipsedSkyIrradianceShare(const glm::dvec3& point, const glm::dvec3& sun_dir, const Moon& moon) const {
  const AtmosphereDomain& domain = sampler_.domain();
  const double length = glm::length(point);
  const glm::dvec3 up = length > 0.0 ? point / length : glm::dvec3(0.0, 0.0, 1.0);
  // Within the shell, as the irradiance lookups take it.
  const glm::dvec3 from = up * std::clamp(length, domain.bottom_radius_m, domain.top_radius_m);
  const glm::dvec3 helper = std::abs(up.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 east = glm::normalize(glm::cross(helper, up)), north = glm::cross(up, east);
  const Spectrum skylight = eclipseSkylight(from, {sun_dir, moon});
  Spectrum eclipsed(0.0f), plain(0.0f);
  for (int b = 0; b < kEclipseIrradianceBands; ++b) {
    const double sin_squared = (b + 0.5) / kEclipseIrradianceBands;
    const double sin_theta = std::sqrt(sin_squared), cos_theta = std::sqrt(1.0 - sin_squared);
    for (int j = 0; j < kEclipseIrradianceAzimuths; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5 * (b % 2)) / kEclipseIrradianceAzimuths;
      const glm::dvec3 dir = up * cos_theta + (east * std::cos(phi) + north * std::sin(phi)) * sin_theta;
      eclipsed += skyRadiance(from, dir, {sun_dir, moon, skylight}).radiance;
      plain += skyRadiance(from, dir, sun_dir).radiance;
    }
  }
  return eclipsedShare(eclipsed, plain);
}

}  // namespace skybake
