#include "runtime/sky.h"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>

#include "data_formats/error.h"
#include "runtime/atmosphere_media.h"
#include "runtime/atmosphere_ray.h"
#include "runtime/ray_quadrature.h"
#include "runtime/single_scattering_ray.h"

namespace skybake {
namespace {

// Below this sun elevation cosine, single Mie scattering toward a point is
// faded out: the difference of two Mie lookups at neighbouring twilight
// texels is noise larger than the signal (Bruneton 2017 does the same).
constexpr double kMieTwilightFadeCosine = 0.01;

// Half-width, in view zenith cosine, of the band around the geometric horizon
// where radiance to a point blends the ground-ray and sky-ray halves of the
// table. Each half is interpolated separately, so at the horizon the two
// estimates of the same segment integral differ by interpolation error; the
// blend removes that step. 0.002 is about 0.1 deg, a few texels of the mu axis
// near the horizon at the default 128.
constexpr double kHorizonBlendCosine = 0.002;

// Radiance toward a point is found two ways. Over long segments, as the
// scattering to the ray's end seen from the camera minus that seen from the
// point (two lookups). Over short ones that difference is a few percent of
// either term, so the tables' interpolation kinks, amplified 30 to 100 times,
// show as seams; there the segment is integrated directly from the
// single-scattering source and the tabulated multiple-scattering source.
// Between the two lengths the results are blended linearly in distance.
// With the sun below the horizon every segment is integrated directly, as
// single scattering along whole rays is (kIntegratedSingleScatteringTopCosine):
// the tables' twilight difference was 4.3 / 4.2 / 3.8 % RMS off on the
// standard set, the direct integral is 3.1 / 3.8 / 3.6 % (reference noise 3 %).
constexpr double kDirectSegmentMaxLength_m = 20000.0;
constexpr double kDifferenceSegmentMinLength_m = 10000.0;
// 4 sub-intervals x 4 Gauss nodes: a vertical 20 km segment holds 17 Mie
// scale heights, 4 per sub-interval, integrated to ~1e-3.
constexpr int kDirectSegmentSubintervals = 4;

// A ray whose closest approach to the planet centre lies within this distance
// below the ground only grazes it. Points along an exactly tangent ray give
// directions that differ by rounding (~1e-16 rad), so the same ray was
// classified as hitting the ground or not from one point to the next, and the
// transmittance to points past the tangent point flickered between 0 and its
// value. 1 mm is far above that rounding (~1e-6 m at 1e10 m) and far below
// any geometry a renderer resolves.
constexpr double kGroundGrazeTolerance_m = 1e-3;

// With the sun below the horizon, single scattering is integrated along the
// view ray at each lookup (integrateSingleScattering) instead of read from
// the tables. There the planet's shadow cuts the rays, and where it cuts
// moves fast with the sun's angles: interpolated between texels the tables
// miss it by tens of percent (measured on a grid of twilight views between
// the texels: 14 % RMS of the sky radiance at the default sizes, 3 % with 4x
// the texels on both the mu_s and nu axes). Multiple scattering, smooth
// there, still comes from its table.
// From the horizon up to this sun elevation (as a zenith cosine, sin 1 deg)
// the integral's weight falls smoothly from 1 to 0, so no step shows as the
// sun sets; the tables are within 1 % of the integral there (0.8 % RMS of the
// sky radiance at sun zenith 89 to 90 deg).
constexpr double kIntegratedSingleScatteringTopCosine = 0.0175;
// Sub-intervals of 4 Gauss nodes over the ray for that integral (the bake
// uses 8): on a grid of twilight views 0.12 % RMS of the sky radiance off a
// 64-sub-interval rule, worst 7 % (long limb rays from 45 to 60 km whose lit
// part is short); 2 sub-intervals 0.43 % RMS, 8 0.04 %. About 2 us per ray on
// one core, 6 times a day lookup (scripts/bench_lookup.sh).
constexpr int kLookupSingleScatteringSegments = 4;
// A bake whose tables hold no rays toward the ground ([scene]
// views_below_horizon = false) integrates such a ray at each lookup: single
// scattering as above, multiple scattering from its tabulated density, over
// this many sub-intervals of 4 Gauss nodes. 4, 8 and 16 gave the same
// validated ground-ray figures to 0.01 point (built-in Earth, standard set).
constexpr int kGroundRaySubintervals = 4;

bool grazesGround(const AtmosphereDomain& domain, const AtmosphereRay& ray) {
  const double closest_approach_m = ray.r * safeSqrt(1.0 - ray.mu * ray.mu);
  return closest_approach_m >= domain.bottom_radius_m - kGroundGrazeTolerance_m;
}

// Where lookups start: the camera, or where its ray enters the atmosphere.
AtmosphereRay enter(const AtmosphereDomain& domain, const glm::dvec3& camera, const glm::dvec3& dir) {
  return atmosphereRay(domain.bottom_radius_m, domain.top_radius_m, camera, dir, 0.0);
}

// Lookups this close outside a baked range count as inside: the range's
// ends come back from the tables' coordinates through a square root (r from
// rho) or an arccosine, which rounds by far less.
constexpr double kRangeAltitudeTolerance_m = 1e-3;
constexpr double kRangeSunZenithTolerance_deg = 1e-6;

double degreesOfCosine(double cosine) { return degreesFromRadians(std::acos(clampCosine(cosine))); }

BakedRanges bakedRangesOf(const AtmosphereDomain& d, double sun_max_zenith_deg) {
  const double thickness_m = d.top_radius_m - d.bottom_radius_m;
  const double high_m = d.radiusAtDistanceToHorizon(d.scattering_rho_max_m) - d.bottom_radius_m;
  return {d.radiusAtDistanceToHorizon(d.scattering_rho_min_m) - d.bottom_radius_m,
          high_m >= thickness_m - kRangeAltitudeTolerance_m ? std::numeric_limits<double>::infinity() : high_m,
          d.scattering_mu_s_coord_max >= 1.0 ? 0.0 : degreesOfCosine(muSFromUnitCoord(d, d.scattering_mu_s_coord_max)),
          d.scattering_mu_s_coord_min <= 0.0 ? sun_max_zenith_deg
                                             : degreesOfCosine(muSFromUnitCoord(d, d.scattering_mu_s_coord_min)),
          thickness_m};
}

RadianceAndTransmittance directSegmentRadiance(const TableSampler& sampler, const BakeTables& t,
                                               const AtmosphereParameters& a,
                                               const MultipleScatteringPhase& multiple_shape, double r, double mu,
                                               double mu_s, double nu, double length, int subintervals,
                                               bool with_single);

}  // namespace

bool BakedRanges::containsAltitude(double altitude_m) const {
  altitude_m = std::min(altitude_m, atmosphere_top_m);
  return altitude_m >= altitude_min_m - kRangeAltitudeTolerance_m &&
         altitude_m <= altitude_max_m + kRangeAltitudeTolerance_m;
}

bool BakedRanges::containsSunZenith(double sun_zenith_deg) const {
  return sun_zenith_deg >= sun_zenith_min_deg - kRangeSunZenithTolerance_deg &&
         sun_zenith_deg <= sun_zenith_max_deg + kRangeSunZenithTolerance_deg;
}

Sky Sky::load(const std::filesystem::path& path) { return Sky(readBakeFile(path)); }

Sky::Sky(BakeFile bake)
    : bake_(std::move(bake)),
      sampler_(bake_.contents.domain, bake_.contents.sizes),
      multiple_shape_(bake_.contents.atmosphere),
      mie_phase_(bake_.contents.atmosphere.mie_phase_g),
      ranges_(bakedRangesOf(sampler_.domain(), bake_.contents.atmosphere.sun_max_zenith_deg)),
      baked_mu_s_min_(std::cos(radiansFromDegrees(ranges_.sun_zenith_max_deg))),
      baked_mu_s_max_(std::cos(radiansFromDegrees(ranges_.sun_zenith_min_deg))) {}

RadianceAndTransmittance Sky::skyRadiance(const glm::dvec3& camera, const glm::dvec3& view_dir,
                                          const glm::dvec3& sun_dir, double shadow_length_m) const {
  const AtmosphereDomain& domain = sampler_.domain();
  const AtmosphereRay start = enter(domain, camera, view_dir);
  if (!start.inside) return {Spectrum(0.0f), Spectrum(1.0f)};
  const double r = start.r;
  const double mu = start.mu;
  const double mu_s = clampCosine(glm::dot(start.origin, sun_dir) / r);
  const double nu = clampCosine(glm::dot(view_dir, sun_dir));
  const bool ground = start.ends_on_ground;
  const BakeTables& t = bake_.tables;

  const Spectrum transmittance =
      ground ? glm::exp(-sampler_.opticalDepthAlongRay(t.optical_depth, r, mu, start.length, true))
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
  if (ground && !domain.scattering_ground_views) {
    // The tables hold no rays toward the ground: integrate this one.
    return {groundRayRadiance({r, mu, mu_s, nu, ground}, shadow, start.length, {r_p, mu_p, mu_s_p, nu, ground},
                              shadow_transmittance),
            transmittance};
  }
  const SingleScattering single = singleScattering({r, mu, mu_s, nu, ground}, shadow, start.length, [&] {
    return SingleScattering{
        sampler_.scattering(t.single_rayleigh, r_p, mu_p, mu_s_p, nu, ground) * shadow_transmittance,
        hasSingleMie() ? sampler_.scattering(t.single_mie, r_p, mu_p, mu_s_p, nu, ground) * shadow_transmittance
                       : Spectrum(0.0f)};
  });
  const Spectrum multiple = sampler_.scattering(t.multiple_scattering, r_p, mu_p, mu_s_p, nu, ground) *
                            multiple_shape_(r_p - domain.bottom_radius_m, nu) * shadow_transmittance;
  const Spectrum radiance = single.rayleigh * static_cast<float>(rayleighPhase(nu)) +
                            single.mie * static_cast<float>(mie_phase_(nu)) +
                            multiple;
  return {radiance, transmittance};
}

namespace {

struct SegmentScattering {
  Spectrum rayleigh;  // over the Rayleigh phase
  Spectrum mie;       // over the Mie phase
  Spectrum multiple;  // radiance (the multiple-scattering shape applied at each end)
};

// In-scattering over [0, d] of the ray (r, mu): the scattering to the ray's
// end seen from its start minus that seen from the point at d, attenuated.
SegmentScattering segmentScattering(const TableSampler& sampler, const BakeTables& t,
                                    const MultipleScatteringPhase& multiple_shape, double r, double mu,
                                    double mu_s, double nu, double d, double shadow, bool ground,
                                    const Spectrum& transmittance) {
  const AtmosphereDomain& domain = sampler.domain();
  const double d_p = std::max(d - shadow, 0.0);
  const double r_p = std::clamp(radiusAlongRay(r, mu, d_p), domain.bottom_radius_m, domain.top_radius_m);
  const double mu_p = cosineAlongRay(r, mu, d_p, r_p);
  const double mu_s_p = clampCosine((r * mu_s + d_p * nu) / r_p);
  const Spectrum shadow_transmittance =
      shadow == 0.0 ? transmittance
                    : glm::exp(-sampler.opticalDepthAlongRay(t.optical_depth, r, mu, d_p, ground));
  auto difference = [&](const Texture4D& table, const Spectrum& scale_here, const Spectrum& scale_there) {
    return glm::max(sampler.scattering(table, r, mu, mu_s, nu, ground) * scale_here -
                        shadow_transmittance * scale_there *
                            sampler.scattering(table, r_p, mu_p, mu_s_p, nu, ground),
                    Spectrum(0.0f));
  };
  const Spectrum one(1.0f);
  return {difference(t.single_rayleigh, one, one),
          t.single_mie.texels.empty() ? Spectrum(0.0f) : difference(t.single_mie, one, one),
          difference(t.multiple_scattering, multiple_shape(r - domain.bottom_radius_m, nu),
                     multiple_shape(r_p - domain.bottom_radius_m, nu))};
}

// In-scattered radiance over [0, length] of the ray (r, mu) by direct
// quadrature of the scattering sources, each attenuated back to the start,
// with the optical depth along the segment integrated from the density
// profiles (a difference of two tabulated depths to the top is two values
// near 30 at the horizon whose difference over 1 km is 0.04: table error
// would dominate it). Also gives the segment's transmittance.
RadianceAndTransmittance directSegmentRadiance(const TableSampler& sampler, const BakeTables& t,
                                               const AtmosphereParameters& a,
                                               const MultipleScatteringPhase& multiple_shape, double r, double mu,
                                               double mu_s, double nu, double length, int subintervals,
                                               bool with_single) {
  const AtmosphereDomain& domain = sampler.domain();
  const AtmosphereMedia media(a);
  const float rayleigh_phase = static_cast<float>(rayleighPhase(nu));
  const float mie_phase = static_cast<float>(cornetteShanksPhase(a.mie_phase_g, nu));
  const double multiple_peak = multiple_shape.peakAt(nu);
  auto altitudeAt = [&](double d) {
    return std::clamp(radiusAlongRay(r, mu, d), domain.bottom_radius_m, domain.top_radius_m) - domain.bottom_radius_m;
  };
  Spectrum sum(0.0f);
  const SpectrumD depth = forEachOpticallyThinNodeWithIntegral<SpectrumD>(
      length, subintervals, -r * mu, [&](double d) { return media.extinction(altitudeAt(d)); },
      largestChannel,
      [&](double d, double w, const SpectrumD& depth_to_d) {
        const double r_d = domain.bottom_radius_m + altitudeAt(d);
        const double mu_d = cosineAlongRay(r, mu, d, r_d);
        const double mu_s_d = clampCosine((r * mu_s + d * nu) / r_d);
        const double altitude = r_d - domain.bottom_radius_m;
        const Spectrum single_source =
            with_single
                ? (a.rayleigh_scattering * (static_cast<float>(media.rayleighDensity(altitude)) * rayleigh_phase) +
                   a.mie_scattering * (static_cast<float>(media.mieDensity(altitude)) * mie_phase)) *
                      (a.sun_irradiance *
                       sampler.transmittanceToSun(t.optical_depth, r_d, mu_s_d, a.sun_angular_radius_rad))
                : Spectrum(0.0f);
        const Spectrum multiple_source =
            sampler.multipleDensity(t.multiple_density, r_d, mu_d, mu_s_d, nu) *
            MultipleScatteringPhase::withPeak(multiple_shape.peakWeightAt(altitude), multiple_peak);
        sum += (single_source + multiple_source) * Spectrum(glm::exp(-depth_to_d)) * static_cast<float>(w);
      });
  return {sum, Spectrum(glm::exp(-depth))};
}

}  // namespace

RadianceAndTransmittance Sky::radianceToPoint(const glm::dvec3& camera, const glm::dvec3& point,
                                              const glm::dvec3& sun_dir, double shadow_length_m) const {
  if (!outputs().radiance_to_points) {
    throw Error(ErrorKind::BadInput,
                "radiance to a point: this bake leaves it out (its scene.outputs lacks \"radiance_to_points\")");
  }
  const AtmosphereDomain& domain = sampler_.domain();
  const glm::dvec3 offset = point - camera;
  const double distance = glm::length(offset);
  if (!(distance > 0.0)) return {Spectrum(0.0f), Spectrum(1.0f)};
  const glm::dvec3 view_dir = offset / distance;
  const AtmosphereRay start = enter(domain, camera, view_dir);
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
  const double direct_weight = std::max(
      std::clamp((kDirectSegmentMaxLength_m - scattering_length) /
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
                                   : direct.transmittance) * w;
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
  const SingleScattering single = singleScattering({r, mu, mu_s, nu, ground}, 0.0, std::max(d - shadow, 0.0), [&] {
    return SingleScattering{s.rayleigh, s.mie * static_cast<float>(mie_fade * mie_fade * (3.0 - 2.0 * mie_fade))};
  });
  return single.rayleigh * static_cast<float>(rayleighPhase(nu)) +
         single.mie * static_cast<float>(mie_phase_(nu)) + s.multiple;
}

double Sky::integratedSingleScatteringWeight(double mu_s) {
  const double x = std::clamp(1.0 - mu_s / kIntegratedSingleScatteringTopCosine, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

SunlitRay Sky::withBakedSun(const SunlitRay& ray) const {
  SunlitRay baked = ray;
  baked.mu_s = std::clamp(ray.mu_s, baked_mu_s_min_, baked_mu_s_max_);
  return baked;
}

void Sky::blendInIntegratedSingleScattering(const SunlitRay& ray, double t_start, double t_end, double weight,
                                            SingleScattering& s) const {
  const SingleScattering integrated = integrateSingleScattering(sampler_, bake_.tables.optical_depth, atmosphere(),
                                                                ray, t_start, t_end, kLookupSingleScatteringSegments);
  const float w = static_cast<float>(weight);
  s.rayleigh += (integrated.rayleigh - s.rayleigh) * w;
  s.mie += (integrated.mie - s.mie) * w;
}

Spectrum Sky::groundRayRadiance(const SunlitRay& ray, double t_start, double t_end, const SunlitRay& from_start,
                                const Spectrum& to_start) const {
  const BakeTables& t = bake_.tables;
  const SingleScattering single = integrateSingleScattering(sampler_, t.optical_depth, atmosphere(),
                                                            withBakedSun(ray), t_start, t_end, kGroundRaySubintervals);
  const SunlitRay baked_from_start = withBakedSun(from_start);
  const RadianceAndTransmittance multiple = directSegmentRadiance(
      sampler_, t, atmosphere(), multiple_shape_, baked_from_start.r, baked_from_start.mu, baked_from_start.mu_s,
      ray.nu, std::max(t_end - t_start, 0.0), kGroundRaySubintervals, false);
  return single.rayleigh * static_cast<float>(rayleighPhase(ray.nu)) +
         single.mie * static_cast<float>(mie_phase_(ray.nu)) +
         multiple.radiance * to_start;
}

RadianceAndTransmittance Sky::receivedRadiance(const glm::dvec3& camera, const glm::dvec3& view_dir,
                                               const glm::dvec3& sun_dir) const {
  const AtmosphereDomain& domain = sampler_.domain();
  RadianceAndTransmittance v = skyRadiance(camera, view_dir, sun_dir);
  const AtmosphereRay start = enter(domain, camera, view_dir);
  if (!start.inside || !start.ends_on_ground) return v;
  const glm::dvec3 ground = start.origin + view_dir * start.length;
  const SunAndSkyIrradiance e = irradiance(ground, glm::normalize(ground), sun_dir);
  v.radiance += v.transmittance * atmosphere().ground_albedo * static_cast<float>(1.0 / kPi) * (e.sun + e.sky);
  return v;
}

SunAndSkyIrradiance Sky::irradiance(const glm::dvec3& point, const glm::dvec3& normal,
                                    const glm::dvec3& sun_dir) const {
  if (!outputs().ground_irradiance) {
    throw Error(ErrorKind::BadInput,
                "irradiance: this bake leaves it out (its scene.outputs lacks \"ground_irradiance\")");
  }
  const AtmosphereDomain& domain = sampler_.domain();
  const double length = glm::length(point);
  const double r = std::clamp(length, domain.bottom_radius_m, domain.top_radius_m);
  const glm::dvec3 up = length > 0.0 ? point / length : glm::dvec3(0.0, 0.0, 1.0);
  const double mu_s = clampCosine(glm::dot(up, sun_dir));
  const BakeTables& t = bake_.tables;
  const Spectrum sky = sampler_.irradiance(t.irradiance, r, mu_s) *
                       static_cast<float>(0.5 * (1.0 + glm::dot(normal, up)));
  const Spectrum sun = atmosphere().sun_irradiance *
                       sampler_.transmittanceToSun(t.optical_depth, r, mu_s, atmosphere().sun_angular_radius_rad) *
                       static_cast<float>(std::max(glm::dot(normal, sun_dir), 0.0));
  return {sun, sky};
}

Spectrum Sky::solarRadiance() const {
  const double alpha = atmosphere().sun_angular_radius_rad;
  if (alpha <= 0.0) return Spectrum(0.0f);
  const double solid_angle_sr = 2.0 * kPi * (1.0 - std::cos(alpha));
  return atmosphere().sun_irradiance / static_cast<float>(solid_angle_sr);
}

Spectrum Sky::transmittance(const glm::dvec3& a, const glm::dvec3& b) const {
  const AtmosphereDomain& domain = sampler_.domain();
  const glm::dvec3 offset = b - a;
  const double distance = glm::length(offset);
  if (!(distance > 0.0)) return Spectrum(1.0f);
  const glm::dvec3 dir = offset / distance;
  const AtmosphereRay start = enter(domain, a, dir);
  const double d = distance - start.moved;
  if (!start.inside || d <= 0.0) return Spectrum(1.0f);
  bool ground = start.ends_on_ground;
  double length = start.length;
  if (ground && d > length) {
    if (!grazesGround(domain, start)) return Spectrum(0.0f);  // the segment passes through the planet
    // Tangent to the ground: the segment goes on past the tangent point.
    ground = false;
    length = distanceToOuterSphere(start.r, start.mu, domain.top_radius_m);
  }
  // Beyond the top the ray is in vacuum: only the part inside counts.
  const double inside = std::min(d, length);
  return glm::exp(-sampler_.opticalDepthAlongRay(bake_.tables.optical_depth, start.r, start.mu, inside, ground));
}

}  // namespace skybake
