#include "runtime/physics/single_scattering_ray.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "runtime/physics/atmosphere_media.h"
#include "runtime/physics/ray_quadrature.h"
#include "runtime/sky_lookup_constants.h"

namespace skybake {

double integratedSingleScatteringWeight(double mu_s) {
  const double x = std::clamp(1.0 - mu_s / kIntegratedSingleScatteringTopCosine, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

SingleScattering integrateSingleScattering(const TableSampler& sampler, const Texture2D& optical_depth,
                                           const AtmosphereParameters& a, const SunlitRay& ray, double t_start,
                                           double t_end, int segments, const MoonAlongRay* moon,
                                           const ColourWavelengths* colour) {
  // A light shaft's shadow can reach past the ray's end: nothing is lit.
  if (!(t_end > t_start)) return {Spectrum(0.0f), Spectrum(0.0f)};
  const AtmosphereMedia media(a);
  const double r = ray.r, mu = ray.mu;
  auto radiusAt = [&](double t) { return std::clamp(radiusAlongRay(r, mu, t), a.bottom_radius_m, a.top_radius_m); };
  SpectrumD rayleigh(0.0), mie(0.0);
  auto node = [&](double t, double w) {
    const double r_t = radiusAt(t);
    const double altitude = r_t - a.bottom_radius_m;
    const double mu_s_t = clampCosine((r * ray.mu_s + t * ray.nu) / r_t);
    // As TableSampler::transmittanceToSun, with one exponential for the
    // sunlight's whole path, to the node and on to the ray's start.
    const TableSampler::SunFromR sun(sampler, r_t, a.sun_angular_radius_rad);
    const double visible = sun.visibleFraction(mu_s_t) * (moon ? moon->visibleSunFraction(t) : 1.0);
    if (visible <= 0.0) return;  // in the planet's shadow or the moon's umbra
    const double sun_coord = sun.muCoord(mu_s_t);
    auto lightFrom = [&](const Texture2D& depths) {
      const Spectrum depth = sun.opticalDepth(depths, sun_coord) +
                             sampler.opticalDepthAlongRay(depths, r, mu, t, ray.ray_intersects_ground);
      return SpectrumD(glm::exp(-depth) * static_cast<float>(visible));
    };
    const double rayleigh_weight = w * media.rayleighDensity(altitude);
    const double mie_weight = w * media.mieDensity(altitude);
    if (colour == nullptr) {
      const SpectrumD light = lightFrom(optical_depth);
      rayleigh += light * rayleigh_weight;
      mie += light * mie_weight;
      return;
    }
    for (size_t g = 0; g < colour->optical_depth.size(); ++g) {
      const SpectrumD light = lightFrom(colour->optical_depth[g]);
      const WavelengthGroupToXyz& to_xyz = colour->to_xyz[g];
      for (int c = 0; c < kCieXyzChannels; ++c) {
        rayleigh[c] += glm::dot(to_xyz.rayleigh[c], light) * rayleigh_weight;
        mie[c] += glm::dot(to_xyz.mie[c], light) * mie_weight;
      }
    }
  };
  // The rule's pieces come from the ray alone; the shadow's edges cut them.
  const ShadowCrossings crossings = planetShadowCrossings(r, mu, ray.mu_s, ray.nu, a.bottom_radius_m, t_end);
  forEachOpticallyThinNodeCutAt(
      t_start, t_end, segments, -r * mu, crossings.distance.data(), crossings.count,
      [&](double t) { return media.largestExtinction(radiusAt(t) - a.bottom_radius_m); }, node);
  // Each wavelength's sun and coefficients are in its X, Y, Z weights.
  if (colour != nullptr) return {Spectrum(rayleigh), Spectrum(mie)};
  return {Spectrum(rayleigh) * a.sun_irradiance * a.rayleigh_scattering,
          Spectrum(mie) * a.sun_irradiance * a.mie_scattering};
}

}  // namespace skybake
