// Radiance scattered toward the camera between it and a point (aerial
// perspective), and the transmittance between them.
#include <algorithm>

#include <glm/geometric.hpp>

#include "data_formats/error.h"
#include "runtime/lookup_geometry.h"
#include "runtime/physics/segment_radiance.h"
#include "runtime/sky.h"
#include "runtime/sky_lookup_constants.h"
#include "runtime/sky_lookup_start.h"

namespace skybake {
namespace {

struct SegmentScattering {
  Spectrum rayleigh;  // over the Rayleigh phase
  Spectrum mie;       // over the Mie phase
  Spectrum multiple;  // radiance (the multiple-scattering shape applied at each end)
  double far_mu_s;    // the sun's zenith cosine at the segment's far end
};

// In-scattering over [0, d] of the ray (r, mu): the scattering to the ray's
// end seen from its start minus that seen from the point at d, attenuated.
SegmentScattering segmentScattering(const TableSampler& sampler, const BakeTables& t,
                                    const MultipleScatteringPhase& multiple_shape, double r, double mu, double mu_s,
                                    double nu, double d, double shadow, bool ground, const Spectrum& transmittance) {
  const AtmosphereDomain& domain = sampler.domain();
  const double d_p = std::max(d - shadow, 0.0);
  const double r_p = std::clamp(radiusAlongRay(r, mu, d_p), domain.bottom_radius_m, domain.top_radius_m);
  const double mu_p = cosineAlongRay(r, mu, d_p, r_p);
  const double mu_s_p = clampCosine((r * mu_s + d_p * nu) / r_p);
  const Spectrum shadow_transmittance =
      shadow == 0.0 ? transmittance : glm::exp(-sampler.opticalDepthAlongRay(t.optical_depth, r, mu, d_p, ground));
  auto difference = [&](const Texture4D& table, const Spectrum& scale_here, const Spectrum& scale_there) {
    return glm::max(sampler.scattering(table, r, mu, mu_s, nu, ground) * scale_here -
                        shadow_transmittance * scale_there * sampler.scattering(table, r_p, mu_p, mu_s_p, nu, ground),
                    Spectrum(0.0f));
  };
  const Spectrum one(1.0f);
  return {difference(t.single_rayleigh, one, one),
          t.single_mie.texels.empty() ? Spectrum(0.0f) : difference(t.single_mie, one, one),
          difference(t.multiple_scattering, multiple_shape(r - domain.bottom_radius_m, nu),
                     multiple_shape(r_p - domain.bottom_radius_m, nu)),
          mu_s_p};
}

}  // namespace

RadianceAndTransmittance Sky::radianceToPoint(const glm::dvec3& camera_given, const glm::dvec3& point_given,
                                              const Sunlight& sun, double shadow_length_m_given) const {
  if (eclipsed(sun)) return eclipsedRadianceToPoint(camera_given, point_given, sun, shadow_length_m_given);
  const glm::dvec3 camera = lookupPosition(camera_given, "camera");
  const glm::dvec3 point = lookupPosition(point_given, "point");
  const glm::dvec3 sun_dir = lookupDirection(sun.direction, "sun direction");
  const double shadow_length_m = lookupShadowLength(shadow_length_m_given);
  requireOneLaneGroup("radianceToPoint");
  if (!outputs().radiance_to_points) {
    throw Error(ErrorKind::BadInput,
                "radiance to a point: this bake leaves it out (its scene.outputs lacks \"radiance_to_points\")");
  }
  const AtmosphereDomain& domain = sampler_.domain();
  const glm::dvec3 offset = point - camera;
  const double distance = glm::length(offset);
  if (!(distance > 0.0)) return {Spectrum(0.0f), Spectrum(1.0f)};
  const glm::dvec3 view_dir = offset / distance;
  const AtmosphereRay start = enterAtmosphere(domain, camera, view_dir);
  const double d = distance - start.moved;
  if (!start.inside || d <= 0.0) return {Spectrum(0.0f), Spectrum(1.0f)};
  const double r = start.r;
  const double mu = start.mu;
  const double mu_s = clampCosine(glm::dot(start.origin, sun_dir) / r);
  const double nu = clampCosine(glm::dot(view_dir, sun_dir));
  const double shadow = std::max(shadow_length_m - start.moved, 0.0);
  const BakeTables& t = bake_.tables;

  const bool ground = start.ends_on_ground;
  const double scattering_length = std::max(d - shadow, 0.0);
  const double direct_weight =
      std::max(std::clamp((kDirectSegmentMaxLength_m - scattering_length) /
                              (kDirectSegmentMaxLength_m - kDifferenceSegmentMinLength_m),
                          0.0, 1.0),
               ground && !domain.scattering_ground_views
                   ? 1.0
                   : integratedSingleScatteringWeight(withBakedSun({r, mu, mu_s, nu, ground}).mu_s));
  Spectrum radiance(0.0f);
  Spectrum transmittance(0.0f);
  if (direct_weight > 0.0) {
    const float w = static_cast<float>(direct_weight);
    const RadianceAndTransmittance direct =
        directSegmentRadiance(sampler_, t, atmosphere(), multiple_shape_, r, mu, mu_s, nu, scattering_length,
                              kDirectSegmentSubintervals, true);
    radiance += direct.radiance * w;
    // With a shadow the segment to the point is longer than the lit part.
    transmittance += (shadow > 0.0 ? glm::exp(-sampler_.opticalDepthAlongRay(t.optical_depth, r, mu, d, ground))
                                   : direct.transmittance) *
                     w;
  }
  if (direct_weight < 1.0) {
    const float w = static_cast<float>(1.0 - direct_weight);
    const Spectrum table_transmittance = glm::exp(-sampler_.opticalDepthAlongRay(t.optical_depth, r, mu, d, ground));
    radiance += differenceSegmentRadiance(r, mu, mu_s, nu, d, shadow, ground, table_transmittance) * w;
    transmittance += table_transmittance * w;
  }
  return {radiance, transmittance};
}

Spectrum Sky::differenceSegmentRadiance(double r, double mu, double mu_s, double nu, double d, double shadow,
                                        bool ground, const Spectrum& transmittance) const {
  const AtmosphereDomain& domain = sampler_.domain();
  const BakeTables& t = bake_.tables;
  SegmentScattering s =
      segmentScattering(sampler_, t, multiple_shape_, r, mu, mu_s, nu, d, shadow, ground, transmittance);
  const double horizon_mu = tangentZenithCosine(r, domain.bottom_radius_m);
  const double from_horizon = mu - horizon_mu;
  if (std::abs(from_horizon) < kHorizonBlendCosine && domain.scattering_ground_views) {
    // Near the geometric horizon, blend with the other half's estimate of the
    // same segment so the result has no step where the halves meet.
    const SegmentScattering other =
        segmentScattering(sampler_, t, multiple_shape_, r, mu, mu_s, nu, d, shadow, !ground, transmittance);
    const double w_sky = 0.5 + 0.5 * from_horizon / kHorizonBlendCosine;  // 1 at +band, 0 at -band
    const float w_this = static_cast<float>(ground ? 1.0 - w_sky : w_sky);
    s.rayleigh = s.rayleigh * w_this + other.rayleigh * (1.0f - w_this);
    s.mie = s.mie * w_this + other.mie * (1.0f - w_this);
    s.multiple = s.multiple * w_this + other.multiple * (1.0f - w_this);
  }
  const double mie_fade = std::clamp(mu_s / kMieTwilightFadeCosine, 0.0, 1.0);
  const SingleScattering single =
      singleScattering({r, mu, mu_s, nu, ground}, 0.0, std::max(d - shadow, 0.0), s.far_mu_s, [&] {
        return SingleScattering{s.rayleigh, s.mie * static_cast<float>(mie_fade * mie_fade * (3.0 - 2.0 * mie_fade))};
      });
  return single.rayleigh * static_cast<float>(rayleighPhase(nu)) + single.mie * static_cast<float>(mie_phase_(nu)) +
         s.multiple;
}

}  // namespace skybake
