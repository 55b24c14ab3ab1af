#include "baker/comparators/hillaire_multiple_scattering.h"

#include <chrono>

#include <glm/geometric.hpp>

#include "baker/stages/optical_depth_table.h"
#include "baker/stages/progress.h"
#include "runtime/physics/atmosphere_media.h"
#include "runtime/physics/atmosphere_ray.h"

namespace skybake {
namespace {

constexpr int kTableSize = 32;         // multiple-scattering table: 32 altitudes x 32 sun cosines
constexpr int kDirectionsPerAxis = 8;  // 8 x 8 directions over the sphere per texel
constexpr int kTableRaySteps = 20;     // steps along each of those rays
constexpr int kViewSteps = 32;         // steps along a view ray

TextureSizes hillaireSizes() {
  TextureSizes s;
  s.transmittance_mu = 256;
  s.transmittance_r = 64;
  return s;
}

// The midpoint ray march of Hillaire's method: `steps` equal steps over
// [0, length] from `origin` along `dir`, calling fn(point, altitude,
// transmittance from the origin to the step's midpoint, step length) at each
// midpoint. Returns the optical depth of the whole segment.
template <typename Fn>
SpectrumD marchMidpoints(const AtmosphereMedia& media, const glm::dvec3& origin, const glm::dvec3& dir, double length,
                         int steps, Fn&& fn) {
  const double dt = length / steps;
  SpectrumD depth(0.0);
  for (int k = 0; k < steps; ++k) {
    const glm::dvec3 p = origin + dir * ((k + 0.5) * dt);
    const double h = glm::length(p) - media.parameters().bottom_radius_m;
    const SpectrumD extinction = media.extinction(h);
    fn(p, h, SpectrumD(glm::exp(-(depth + extinction * (0.5 * dt)))), dt);
    depth += extinction * dt;
  }
  return depth;
}

}  // namespace

HillaireMultipleScattering::HillaireMultipleScattering(const AtmosphereParameters& a)
    : a_(a), sizes_(hillaireSizes()), sampler_(AtmosphereDomain::fromParameters(a), sizes_) {
  const auto start = std::chrono::steady_clock::now();
  SilentProgress silent;
  optical_depth_ = computeOpticalDepthTable({a_, sampler_, silent});
  const AtmosphereMedia media(a_);
  multiple_ = Texture2D(kTableSize, kTableSize);
  const double thickness = a_.top_radius_m - a_.bottom_radius_m;
#pragma omp parallel for schedule(dynamic)
  for (int i_h = 0; i_h < kTableSize; ++i_h) {
    for (int i_s = 0; i_s < kTableSize; ++i_s) {
      const double h = (i_h + 0.5) / kTableSize * thickness;
      const double mu_s = -1.0 + 2.0 * (i_s + 0.5) / kTableSize;
      const glm::dvec3 x(0.0, 0.0, a_.bottom_radius_m + h);
      const glm::dvec3 sun(std::sqrt(std::max(0.0, 1.0 - mu_s * mu_s)), 0.0, mu_s);
      SpectrumD second_order(0.0), transfer(0.0);  // L_2nd and f_ms, isotropic phase
      for (int i = 0; i < kDirectionsPerAxis; ++i) {
        for (int j = 0; j < kDirectionsPerAxis; ++j) {
          // Equal-area directions: cos(theta) uniform, phi uniform.
          const double cos_t = 1.0 - 2.0 * (i + 0.5) / kDirectionsPerAxis;
          const double phi = 2.0 * kPi * (j + 0.5) / kDirectionsPerAxis;
          const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
          const glm::dvec3 dir(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t);
          const double r = glm::length(x);
          const bool ground = rayIntersectsSphere(r, cos_t, a_.bottom_radius_m);
          const double length = distanceToAtmosphereEnd(r, cos_t, a_.bottom_radius_m, a_.top_radius_m, ground);
          const SpectrumD depth = marchMidpoints(
              media, x, dir, length, kTableRaySteps,
              [&](const glm::dvec3& p, double hp, const SpectrumD& t, double dt) {
                const SpectrumD scattering = SpectrumD(a_.rayleigh_scattering) * media.rayleighDensity(hp) +
                                             SpectrumD(a_.mie_scattering) * media.mieDensity(hp);
                // Light scattered once (isotropic phase 1 / 4 pi) toward x.
                second_order += t * scattering * SpectrumD(transmittanceToSun(p, sun)) * (dt / (4.0 * kPi));
                transfer += t * scattering * dt;
              });
          if (ground) second_order += glm::exp(-depth) * litGround(x + dir * length, sun);
        }
      }
      // The mean over directions: second_order is the mean radiance of light
      // scattered once arriving at x (per unit sun irradiance), transfer the
      // fraction of isotropically scattered light that scatters again.
      const double n = kDirectionsPerAxis * kDirectionsPerAxis;
      second_order /= n;
      transfer /= n;
      multiple_.at(i_s, i_h) = Spectrum(second_order / (SpectrumD(1.0) - glm::min(transfer, SpectrumD(0.99))));
    }
  }
  precompute_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

size_t HillaireMultipleScattering::memoryBytes() const {
  return (optical_depth_.texels.size() + multiple_.texels.size()) * sizeof(float) * a_.channelCount();
}

Spectrum HillaireMultipleScattering::transmittanceToSun(const glm::dvec3& p, const glm::dvec3& sun) const {
  const double r = std::max(glm::length(p), a_.bottom_radius_m);
  const double mu_s = glm::dot(p, sun) / glm::length(p);
  if (rayIntersectsSphere(r, mu_s, a_.bottom_radius_m)) return Spectrum(0.0f);
  return glm::exp(-sampler_.opticalDepthToTop(optical_depth_, std::min(r, a_.top_radius_m), mu_s));
}

SpectrumD HillaireMultipleScattering::litGround(const glm::dvec3& ground_point, const glm::dvec3& sun) const {
  const double g_mu_s = glm::dot(glm::normalize(ground_point), sun);
  if (g_mu_s <= 0.0) return SpectrumD(0.0);
  return SpectrumD(a_.ground_albedo) * (g_mu_s / kPi) * SpectrumD(transmittanceToSun(ground_point, sun));
}

Spectrum HillaireMultipleScattering::multipleScattering(double altitude, double mu_s) const {
  const double thickness = a_.top_radius_m - a_.bottom_radius_m;
  return sampleBilinear(multiple_, {0.5 * (mu_s + 1.0), std::clamp(altitude / thickness, 0.0, 1.0)});
}

RadianceAndTransmittance HillaireMultipleScattering::received(const glm::dvec3& camera, const glm::dvec3& view,
                                                              const glm::dvec3& sun) const {
  const AtmosphereMedia media(a_);
  const AtmosphereRay ray = atmosphereRay(a_.bottom_radius_m, a_.top_radius_m, camera, view, 0.0);
  if (!ray.inside) return {Spectrum(0.0f), Spectrum(1.0f)};
  const glm::dvec3 origin = ray.origin;
  const bool ground = ray.ends_on_ground;
  const double length = ray.length;
  const double nu = glm::dot(view, sun);
  const double p_r = rayleighPhase(nu), p_m = cornetteShanksPhase(a_.mie_phase_g, nu);
  SpectrumD radiance(0.0);
  const SpectrumD depth = marchMidpoints(
      media, origin, view, length, kViewSteps, [&](const glm::dvec3& p, double h, const SpectrumD& t, double dt) {
        const double rayleigh = media.rayleighDensity(h), mie = media.mieDensity(h);
        const SpectrumD single =
            (SpectrumD(a_.rayleigh_scattering) * (rayleigh * p_r) + SpectrumD(a_.mie_scattering) * (mie * p_m)) *
            SpectrumD(transmittanceToSun(p, sun));
        const SpectrumD scattering = SpectrumD(a_.rayleigh_scattering) * rayleigh + SpectrumD(a_.mie_scattering) * mie;
        const SpectrumD multiple = scattering * SpectrumD(multipleScattering(h, glm::dot(glm::normalize(p), sun)));
        radiance += t * (single + multiple) * dt;
      });
  radiance *= SpectrumD(a_.sun_irradiance);
  const SpectrumD transmittance = glm::exp(-depth);
  if (ground) radiance += transmittance * litGround(origin + view * length, sun) * SpectrumD(a_.sun_irradiance);
  return {Spectrum(radiance), Spectrum(transmittance)};
}

}  // namespace skybake
