// Sky radiance along a view ray, the light a viewer receives with the lit
// ground, and the sun disk's radiance.
#include <algorithm>

#include <glm/geometric.hpp>

#include "runtime/lookup_geometry.h"
#include "runtime/physics/segment_radiance.h"
#include "runtime/sky.h"
#include "runtime/sky_lookup_constants.h"
#include "runtime/sky_lookup_start.h"

namespace skybake {

RadianceAndTransmittance Sky::skyRadiance(const glm::dvec3& camera, const glm::dvec3& view_dir, const Sunlight& sun,
                                          double shadow_length_m) const {
  if (eclipsed(sun)) return eclipsedSkyRadiance(camera, view_dir, sun, shadow_length_m);
  const SkyRadianceParts p = skyRadianceParts(camera, view_dir, sun.direction, shadow_length_m);
  if (!p.inside) return {Spectrum(0.0f), Spectrum(1.0f)};
  return {p.single.rayleigh * static_cast<float>(rayleighPhase(p.nu)) +
              p.single.mie * static_cast<float>(mie_phase_(p.nu)) + p.multiple,
          p.transmittance};
}

Sky::SkyRadianceParts Sky::skyRadianceParts(const glm::dvec3& camera_given, const glm::dvec3& view_dir_given,
                                            const glm::dvec3& sun_dir_given, double shadow_length_m_given) const {
  const auto [camera, view_dir, sun_dir] = checkedView(camera_given, view_dir_given, sun_dir_given);
  const double shadow_length_m = lookupShadowLength(shadow_length_m_given);
  requireOneLaneGroup("skyRadiance");
  const AtmosphereDomain& domain = sampler_.domain();
  SkyRadianceParts parts;
  parts.start = enterAtmosphere(domain, camera, view_dir);
  const AtmosphereRay& start = parts.start;
  parts.inside = start.inside;
  if (!start.inside) return parts;
  const double r = start.r;
  const double mu = start.mu;
  const double mu_s = clampCosine(glm::dot(start.origin, sun_dir) / r);
  const double nu = clampCosine(glm::dot(view_dir, sun_dir));
  parts.mu_s = mu_s;
  parts.nu = nu;
  const bool ground = start.ends_on_ground;
  const BakeTables& t = bake_.tables;

  parts.transmittance = ground ? glm::exp(-sampler_.opticalDepthAlongRay(t.optical_depth, r, mu, start.length, true))
                               : glm::exp(-sampler_.opticalDepthToTop(t.optical_depth, r, mu));

  // Light shafts: only the part of the ray beyond the shadow scatters, seen
  // through the shadowed part. Without a shadow that part starts here; a
  // shadow longer than the ray leaves nothing lit (looked up past the ray's
  // end, the tables gave light from nowhere: 36 times the unshadowed sky).
  const double shadow = std::clamp(shadow_length_m - start.moved, 0.0, start.length);
  double r_p = r, mu_p = mu, mu_s_p = mu_s;
  Spectrum shadow_transmittance(1.0f);
  if (shadow > 0.0) {
    r_p = std::clamp(radiusAlongRay(r, mu, shadow), domain.bottom_radius_m, domain.top_radius_m);
    mu_p = cosineAlongRay(r, mu, shadow, r_p);
    mu_s_p = clampCosine((r * mu_s + shadow * nu) / r_p);
    shadow_transmittance = glm::exp(-sampler_.opticalDepthAlongRay(t.optical_depth, r, mu, shadow, ground));
  }
  parts.lit_from_m = shadow;
  if (ground && !domain.scattering_ground_views) {
    // The tables hold no rays toward the ground: integrate this one.
    groundRayRadiance({r, mu, mu_s, nu, ground}, shadow, start.length, {r_p, mu_p, mu_s_p, nu, ground},
                      shadow_transmittance, parts.single, parts.multiple);
    return parts;
  }
  parts.single = singleScattering({r, mu, mu_s, nu, ground}, shadow, start.length, mu_s_p, [&] {
    return SingleScattering{
        sampler_.scattering(t.single_rayleigh, r_p, mu_p, mu_s_p, nu, ground) * shadow_transmittance,
        hasSingleMie() ? sampler_.scattering(t.single_mie, r_p, mu_p, mu_s_p, nu, ground) * shadow_transmittance
                       : Spectrum(0.0f)};
  });
  parts.multiple = sampler_.scattering(t.multiple_scattering, r_p, mu_p, mu_s_p, nu, ground) *
                   multiple_shape_(r_p - domain.bottom_radius_m, nu) * shadow_transmittance;
  return parts;
}

void Sky::groundRayRadiance(const SunlitRay& ray, double t_start, double t_end, const SunlitRay& from_start,
                            const Spectrum& to_start, SingleScattering& single, Spectrum& multiple) const {
  const BakeTables& t = bake_.tables;
  single = integratedSingleScattering(withBakedSun(ray), t_start, t_end, kGroundRaySubintervals);
  const SunlitRay baked_from_start = withBakedSun(from_start);
  const RadianceAndTransmittance tabulated_density = directSegmentRadiance(
      sampler_, t, atmosphere(), multiple_shape_, baked_from_start.r, baked_from_start.mu, baked_from_start.mu_s,
      ray.nu, std::max(t_end - t_start, 0.0), kGroundRaySubintervals, false);
  multiple = tabulated_density.radiance * to_start;
}

RadianceAndTransmittance Sky::receivedRadiance(const glm::dvec3& camera_given, const glm::dvec3& view_dir_given,
                                               const Sunlight& sun) const {
  // The sun direction is checked by the lookups below, each as given (the
  // check gives a checked direction back unchanged).
  const glm::dvec3 camera = lookupPosition(camera_given, "camera");
  const glm::dvec3 view_dir = lookupDirection(view_dir_given, "view direction");
  RadianceAndTransmittance v = skyRadiance(camera, view_dir, sun);
  const AtmosphereRay start = enterAtmosphere(sampler_.domain(), camera, view_dir);
  if (!start.inside || !start.ends_on_ground) return v;
  // The lit ground: the sun the moon leaves it and its own skylight share
  // (irradiance takes no camera's).
  const glm::dvec3 ground = start.origin + view_dir * start.length;
  const SunAndSkyIrradiance e = irradiance(ground, glm::normalize(ground), sun);
  v.radiance += v.transmittance * atmosphere().ground_albedo * static_cast<float>(1.0 / kPi) * (e.sun + e.sky);
  return v;
}

Spectrum Sky::solarRadiance() const {
  requireOneLaneGroup("solarRadiance");
  const double alpha = atmosphere().sun_angular_radius_rad;
  if (alpha <= 0.0) return Spectrum(0.0f);
  const double solid_angle_sr = 2.0 * kPi * (1.0 - std::cos(alpha));
  return atmosphere().sun_irradiance / static_cast<float>(solid_angle_sr);
}

}  // namespace skybake
