// Why the budget is computed this way:
//  - Power in. A parallel beam of irradiance E_sun crosses the top sphere's
//    cross-section pi R_top^2. A sun of finite angular radius only spreads the
//    beam's directions by that radius; the power is the same.
//  - Power out, diffuse. By symmetry about the sun's axis the flux leaving a
//    point of the top sphere depends only on the sun's zenith cosine mu_s
//    there, and the area of the top sphere between mu_s and mu_s + dmu_s is
//    2 pi R_top^2 dmu_s. The outgoing radiance along an upward direction is
//    what a camera at the top sees looking the opposite way, down into the
//    atmosphere: Sky::receivedRadiance (in-scattering, plus for rays that end
//    on the ground the transmitted radiance of the lit Lambertian ground).
//  - Power out, direct. Rays of the beam with impact parameter b between the
//    ground and the top radius cross the atmosphere along a chord; their
//    unscattered part T(chord) leaves. Rays with b < R_bottom end on the
//    ground, whose reflection is already in the diffuse term.
//  - Absorbed. The ground absorbs (1 - albedo) of its sun and sky
//    irradiance; the atmosphere of a conservative bake absorbs nothing. In an
//    absorbing atmosphere the budget does not close: the air's absorption is
//    not counted, on purpose (the imbalance then measures it).
//  - The sun disk. Sky fades the sun over the disk's angular diameter where
//    it crosses a horizon. Over the atmosphere the fade is a symmetric ramp
//    and moves light across the terminator without changing its total; on
//    the ground it multiplies a cosine that vanishes at the horizon: the
//    integral of the direct irradiance over mu_s (E_sun / 2 for a point sun)
//    loses E_sun alpha^2 / 20, 2e-6 of the power in for the Sun's angular
//    radius alpha = 4.65 mrad (measured without air; the conservative case's
//    budget moves by < 1e-4 between a point sun and a 0.05 rad one). So the
//    budget treats the sun as a point, with panel edges at the ends of the
//    ground's ramp so that its kinks do not spoil the quadrature.
//  - Suns below the tables. The scattering and irradiance tables stop at
//    mu_s_min, below which Sky scales their value there by its night
//    continuation (runtime/physics/night_sky.h). The flux beyond is twilight that
//    keeps dimming; the budget extrapolates it with the decay rate the tables
//    hold at their edge, and keeps the edge's value over the whole night
//    side (the tables clamped, as lookups were before the continuation) as
//    an upper bound.
#include "baker/stress/energy_budget.h"
#include "data_formats/angles.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "baker/numerics/gauss_legendre.h"
#include "data_formats/parameterization/ray_sphere.h"
#include "data_formats/parameterization/texture_mapping.h"
#include "runtime/physics/phase_functions.h"

namespace skybake {
namespace {

// Above mu_s_min, the step in sun zenith cosine over which the decay rate of
// a twilight flux is measured to extrapolate it below the tables. It lies
// within the first texel interval of the mu_s axis at every stress size (32
// texels at most, whose first interval spans ~0.03 in mu_s for Earth), so the
// rate is the one the tables themselves hold there.
constexpr double kBelowDomainSlopeStep = 0.01;

// Panels of equal width over the unscattered beam's impact parameter
// [R_bottom, R_top]: for Earth each is 7.5 km, about one Rayleigh scale
// height, over which the chord's transmittance is smooth enough for a
// low-order rule (doubling the nodes changes the budget by 1e-6).
constexpr int kImpactPanels = 8;

// A value at a node, or an integral, with the lookups it took.
struct LookupSum {
  SpectrumD value{0.0};
  long long lookups = 0;
};

// Sorted edges of panels over [lo, hi] with the given interior edges (those
// outside (lo, hi) are dropped).
std::vector<double> panelEdges(double lo, double hi, std::vector<double> interior,
                               const std::vector<double>& more_interior = {}) {
  std::vector<double> edges{lo, hi};
  interior.insert(interior.end(), more_interior.begin(), more_interior.end());
  for (double x : interior) {
    if (x > lo && x < hi) edges.push_back(x);
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

// The integral over the panels of f(x) dx, f evaluated at the nodes on
// OpenMP threads and summed in node order (the same result on any number of
// threads).
template <typename Fn>
LookupSum integrateOnPanels(const GaussLegendreRule& rule, const std::vector<double>& edges, Fn&& f) {
  std::vector<double> xs, ws;
  forEachGaussLegendreNodeOnPanels(rule, edges, [&](double x, double w) {
    xs.push_back(x);
    ws.push_back(w);
  });
  std::vector<LookupSum> values(xs.size());
#pragma omp parallel for schedule(dynamic)
  for (long i = 0; i < static_cast<long>(xs.size()); ++i) values[i] = f(xs[i]);
  LookupSum out;
  for (size_t i = 0; i < xs.size(); ++i) {
    out.value += values[i].value * ws[i];
    out.lookups += values[i].lookups;
  }
  return out;
}

// Unit vector toward a sun at zenith cosine mu_s above a point on the +z axis.
glm::dvec3 sunDirection(double mu_s) { return directionFromZenithCosineAzimuth(mu_s, 0.0); }

// Zenith cosine of the ray from radius r tangent to the ground (< 0).
double groundHorizonCosine(double bottom_m, double r_m) { return -safeSqrt(1.0 - (bottom_m / r_m) * (bottom_m / r_m)); }

// Upward spectral flux through the top sphere, W m^-2 nm^-1, at a point with
// the sun at zenith cosine mu_s: the integral over downward view directions
// of received radiance times |mu|. The view zenith cosine is split at the
// ground horizon h (ray lengths, and so radiance, have a square-root
// singularity there) and each half integrated in s with mu = h -+ s^2, which
// removes the singularity and puts nodes close to the horizon.
LookupSum upwardFluxAtTop(const EnergyBudgetLookups& sky, double mu_s, const GaussLegendreRule& zenith_rule,
                          const GaussLegendreRule& azimuth_rule) {
  const AtmosphereParameters& a = sky.atmosphere;
  const glm::dvec3 camera(0.0, 0.0, a.top_radius_m);
  const glm::dvec3 sun = sunDirection(mu_s);
  const double h = groundHorizonCosine(a.bottom_radius_m, a.top_radius_m);
  LookupSum out;
  auto addViewZenith = [&](double mu, double weight_dmu) {
    const double sin_theta = safeSqrt(1.0 - mu * mu);
    forEachGaussLegendreNode(azimuth_rule, 0.0, kPi, [&](double phi, double w_phi) {
      const glm::dvec3 view(sin_theta * std::cos(phi), sin_theta * std::sin(phi), mu);
      out.value += sky.received_radiance(camera, view, sun) * (weight_dmu * std::abs(mu) * w_phi);
      ++out.lookups;
    });
  };
  // Rays that end on the ground: mu = h - s^2 over [-1, h].
  forEachGaussLegendreNode(zenith_rule, 0.0, std::sqrt(1.0 + h),
                           [&](double s, double w) { addViewZenith(h - s * s, 2.0 * s * w); });
  // Rays that cross the atmosphere and leave it again: mu = h + s^2 over [h, 0].
  forEachGaussLegendreNode(zenith_rule, 0.0, std::sqrt(-h),
                           [&](double s, double w) { addViewZenith(h + s * s, 2.0 * s * w); });
  out.value *= 2.0;  // azimuths (pi, 2 pi) mirror (0, pi) across the sun's vertical plane
  return out;
}

// The integral over sun zenith cosines in [-1, mu_s_min] of a flux known from
// the tables only down to mu_s_min: f(mu_s_min) exp(k (mu_s - mu_s_min)),
// with k the decay rate between mu_s_min and mu_s_min + step. A flux that does
// not decay there is taken at its clamped value (the upper bound).
struct BelowDomain {
  SpectrumD extrapolated{0.0};
  SpectrumD clamped{0.0};
};
BelowDomain integralBelowDomain(const SpectrumD& at_min, const SpectrumD& above_min, double mu_s_min) {
  BelowDomain out;
  const double width = mu_s_min + 1.0;
  if (width <= 0.0) return out;
  out.clamped = at_min * width;
  out.extrapolated = out.clamped;
  for (int c = 0; c < kMaxChannels; ++c) {
    if (at_min[c] > 0.0 && above_min[c] > at_min[c]) {
      const double k = std::log(above_min[c] / at_min[c]) / kBelowDomainSlopeStep;
      out.extrapolated[c] = at_min[c] / k * (1.0 - std::exp(-k * width));
    }
  }
  return out;
}

}  // namespace

SpectrumD EnergyBudget::relativeImbalance() const {
  SpectrumD out(0.0);
  const SpectrumD balance = power_in_W_per_nm - powerOut_W_per_nm() - ground_absorbed_W_per_nm;
  for (int c = 0; c < kMaxChannels; ++c) {
    out[c] = power_in_W_per_nm[c] > 0.0 ? balance[c] / power_in_W_per_nm[c] : 0.0;
  }
  return out;
}

EnergyBudgetLookups energyBudgetLookups(const Sky& sky) {
  EnergyBudgetLookups lookups;
  lookups.atmosphere = sky.atmosphere();
  lookups.mu_s_min = sky.atmosphere().sunMuSMin();
  lookups.received_radiance = [&sky](const glm::dvec3& camera, const glm::dvec3& view, const glm::dvec3& sun) {
    return SpectrumD(sky.receivedRadiance(camera, view, sun).radiance);
  };
  lookups.transmittance = [&sky](const glm::dvec3& camera, const glm::dvec3& view) {
    // The transmittance does not depend on the sun; any direction will do.
    return SpectrumD(sky.skyRadiance(camera, view, view).transmittance);
  };
  lookups.ground_irradiance = [&sky](const glm::dvec3& ground_point, const glm::dvec3& sun) {
    return sky.irradiance(ground_point, glm::normalize(ground_point), sun);
  };
  // Radiance from the top: the scattering tables' mu_s texels. On the
  // ground: the irradiance table's mu_s texels (sky) and the transmittance
  // table's mu texels of its ground row (sun).
  const AtmosphereDomain& domain = sky.sampler().domain();
  const TextureSizes& sizes = sky.contents().sizes;
  for (int i = 0; i < sizes.scattering_mu_s; ++i) {
    lookups.radiance_kinks_mu_s.push_back(muSFromScatteringTexel(domain, ScatteringSizes::fromTextureSizes(sizes), i));
  }
  for (int i = 0; i < sizes.irradiance_mu_s; ++i) {
    lookups.ground_irradiance_kinks_mu_s.push_back(muSFromIrradianceTexel(domain, sizes.irradiance_mu_s, i));
  }
  for (int i = 0; i < sizes.transmittance_mu; ++i) {
    lookups.ground_irradiance_kinks_mu_s.push_back(
        transmittanceTexelConfig(domain, sizes.transmittance_mu, sizes.transmittance_r, i, 0).mu);
  }
  return lookups;
}

EnergyBudget computeEnergyBudget(const Sky& sky, const EnergyBudgetQuadrature& quadrature) {
  return computeEnergyBudget(energyBudgetLookups(sky), quadrature);
}

EnergyBudget computeEnergyBudget(const EnergyBudgetLookups& sky, const EnergyBudgetQuadrature& q) {
  const AtmosphereParameters& a = sky.atmosphere;
  const double bottom = a.bottom_radius_m;
  const double top = a.top_radius_m;
  const double mu_s_min = sky.mu_s_min;
  const SpectrumD sun_irradiance = SpectrumD(a.sun_irradiance);
  const GaussLegendreRule sun_rule = gaussLegendreRule(q.sun_zenith_nodes);
  const GaussLegendreRule zenith_rule = gaussLegendreRule(q.view_zenith_nodes);
  const GaussLegendreRule azimuth_rule = gaussLegendreRule(q.view_azimuth_nodes);
  const GaussLegendreRule impact_rule = gaussLegendreRule(q.impact_nodes);
  EnergyBudget budget;

  budget.power_in_W_per_nm = sun_irradiance * (kPi * top * top);

  // Diffuse out. Panel edges where the flux at the top changes character:
  // the sun crossing the top's own ground horizon (h), the zenith plane, and
  // the ground's terminator entering the part of the ground seen from the
  // top (-h); and where the lookups change slope.
  const double h = groundHorizonCosine(bottom, top);
  auto flux = [&](double mu_s) { return upwardFluxAtTop(sky, mu_s, zenith_rule, azimuth_rule); };
  const LookupSum day =
      integrateOnPanels(sun_rule, panelEdges(mu_s_min, 1.0, {h, 0.0, -h}, sky.radiance_kinks_mu_s), flux);
  const LookupSum at_min = flux(mu_s_min);
  const LookupSum above_min = flux(mu_s_min + kBelowDomainSlopeStep);
  const BelowDomain night = integralBelowDomain(at_min.value, above_min.value, mu_s_min);
  const double top_area_per_mu_s = 2.0 * kPi * top * top;
  budget.diffuse_out_W_per_nm = (day.value + night.extrapolated) * top_area_per_mu_s;
  budget.diffuse_out_below_domain_W_per_nm = night.extrapolated * top_area_per_mu_s;
  budget.diffuse_out_below_domain_clamped_W_per_nm = night.clamped * top_area_per_mu_s;
  budget.lookups += day.lookups + at_min.lookups + above_min.lookups;

  // Direct out: sum over impact parameters b of T(chord) 2 pi b db. The chord
  // is the vertical ray down from the top at horizontal offset b.
  std::vector<double> impact_edges;
  for (int i = 0; i <= kImpactPanels; ++i) impact_edges.push_back(bottom + (top - bottom) * i / kImpactPanels);
  const LookupSum transmitted_area_m2 = integrateOnPanels(impact_rule, impact_edges, [&](double b) {
    const glm::dvec3 entry(b, 0.0, safeSqrt(top * top - b * b));
    const glm::dvec3 down(0.0, 0.0, -1.0);
    return LookupSum{sky.transmittance(entry, down) * (2.0 * kPi * b), 1};
  });
  budget.direct_out_W_per_nm = sun_irradiance * transmitted_area_m2.value;
  budget.lookups += transmitted_area_m2.lookups;

  // Absorbed: irradiance on the ground over the ground sphere. The sun's
  // part is exact for any sun angle (transmittance is not clamped); the
  // sky's part comes from the irradiance table, clamped below mu_s_min.
  const glm::dvec3 ground_point(0.0, 0.0, bottom);
  const double ramp = a.sun_angular_radius_rad;  // the disk's half-size in mu_s at the ground
  auto sunIrradiance = [&](double mu_s) {
    return LookupSum{SpectrumD(sky.ground_irradiance(ground_point, sunDirection(mu_s)).sun), 1};
  };
  auto skyIrradiance = [&](double mu_s) {
    return LookupSum{SpectrumD(sky.ground_irradiance(ground_point, sunDirection(mu_s)).sky), 1};
  };
  const std::vector<double> ramp_edges{-ramp, 0.0, ramp};
  const LookupSum sun_part =
      integrateOnPanels(sun_rule, panelEdges(-1.0, 1.0, ramp_edges, sky.ground_irradiance_kinks_mu_s), sunIrradiance);
  const LookupSum sky_part = integrateOnPanels(
      sun_rule, panelEdges(mu_s_min, 1.0, ramp_edges, sky.ground_irradiance_kinks_mu_s), skyIrradiance);
  const BelowDomain sky_night = integralBelowDomain(skyIrradiance(mu_s_min).value,
                                                    skyIrradiance(mu_s_min + kBelowDomainSlopeStep).value, mu_s_min);
  const SpectrumD absorptance = SpectrumD(1.0) - SpectrumD(a.ground_albedo);
  const double ground_area_per_mu_s = 2.0 * kPi * bottom * bottom;
  budget.ground_absorbed_W_per_nm =
      absorptance * (sun_part.value + sky_part.value + sky_night.extrapolated) * ground_area_per_mu_s;
  budget.ground_absorbed_below_domain_W_per_nm = absorptance * sky_night.extrapolated * ground_area_per_mu_s;
  budget.ground_absorbed_below_domain_clamped_W_per_nm = absorptance * sky_night.clamped * ground_area_per_mu_s;
  budget.lookups += sun_part.lookups + sky_part.lookups + 2;
  return budget;
}

}  // namespace skybake
