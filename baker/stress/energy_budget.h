// The energy budget of a bake, measured through the runtime's lookups (Sky):
// the sunlight the planet and its atmosphere intercept must leave through the
// top of the atmosphere (scattered, reflected or unscattered) or be absorbed
// by the ground. In an atmosphere that does not absorb, the imbalance
// (in - out - absorbed) / in is the bake's energy error: light lost or
// created by truncated orders, coarse tables or a defect in a stage.
//
// Powers are spectral, in W nm^-1 (the sun's spectral irradiance times an
// area), one lane per channel of the bake.
#pragma once

#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "data_formats/config/atmosphere_parameters.h"
#include "runtime/sky.h"

namespace skybake {

// The lookups the budget integrates, in Sky's units and conventions
// (positions in metres from the planet centre, unit directions, spectral
// radiance and irradiance). Any model of the sky can be measured: the bake
// through Sky, or a table-free one whose budget must close (a check of the
// integration itself).
struct EnergyBudgetLookups {
  AtmosphereParameters atmosphere;
  // Suns lower than this zenith cosine are looked up as if at it (the
  // tables' edge); -1 where every sun angle is covered.
  double mu_s_min = -1.0;
  // What a camera receives along the view ray, the sun disk aside (see
  // Sky::receivedRadiance).
  std::function<SpectrumD(const glm::dvec3& camera, const glm::dvec3& view, const glm::dvec3& sun)> received_radiance;
  // Transmittance from the camera along the ray to where it leaves the
  // atmosphere or meets the ground.
  std::function<SpectrumD(const glm::dvec3& camera, const glm::dvec3& view)> transmittance;
  // Sun and sky irradiance on a horizontal surface at a point on the ground.
  std::function<SunAndSkyIrradiance(const glm::dvec3& ground_point, const glm::dvec3& sun)> ground_irradiance;
  // Sun zenith cosines where the lookups change slope (texel centres of the
  // tables, between which they interpolate linearly): panel edges of the
  // integrals over the sun angle, so that each panel holds a smooth piece.
  // Of received_radiance from the top, and of ground_irradiance.
  std::vector<double> radiance_kinks_mu_s;
  std::vector<double> ground_irradiance_kinks_mu_s;
};

// The bake's lookups, through `sky` (which must outlive the result).
EnergyBudgetLookups energyBudgetLookups(const Sky& sky);

// Gauss-Legendre nodes per panel for each integral of the budget; doubled()
// doubles every count, to show that the budget has converged.
struct EnergyBudgetQuadrature {
  int sun_zenith_nodes = 4;     // per panel of sun zenith cosine (a panel between neighbouring texels)
  int view_zenith_nodes = 12;   // per half of the downward view directions (ground rays, sky rays)
  int view_azimuth_nodes = 12;  // over azimuth [0, pi] from the sun's vertical plane (the flux is symmetric)
  int impact_nodes = 6;         // per panel of the unscattered beam's impact parameter (8 panels)

  EnergyBudgetQuadrature doubled() const {
    return {2 * sun_zenith_nodes, 2 * view_zenith_nodes, 2 * view_azimuth_nodes, 2 * impact_nodes};
  }
};

struct EnergyBudget {
  // The sun's spectral irradiance on the top sphere's cross-section,
  // E_sun pi R_top^2: a parallel beam (see energy_budget.cpp on the disk).
  SpectrumD power_in_W_per_nm{0.0};
  // Scattered and ground-reflected light leaving the top sphere: the
  // radiance a camera at the top receives looking down into the atmosphere,
  // times |cos|, over the lower hemisphere, over the whole top sphere.
  SpectrumD diffuse_out_W_per_nm{0.0};
  // The part of diffuse_out from where the sun lies below the tables' lowest
  // sun angle (sun zenith cosine < mu_s_min), extrapolated from the tables'
  // decay at their edge; and what the tables clamped to their edge would
  // give there (an upper bound: Sky's night continuation only dims them).
  SpectrumD diffuse_out_below_domain_W_per_nm{0.0};
  SpectrumD diffuse_out_below_domain_clamped_W_per_nm{0.0};
  // Sunlight that crosses the atmosphere without meeting the ground or
  // scattering: impact parameters between the ground and the top radius.
  SpectrumD direct_out_W_per_nm{0.0};
  // (1 - albedo) times the sun and sky irradiance over the ground sphere.
  SpectrumD ground_absorbed_W_per_nm{0.0};
  // Same extrapolation and upper bound as for diffuse_out, for the sky
  // irradiance on the night side beyond mu_s_min.
  SpectrumD ground_absorbed_below_domain_W_per_nm{0.0};
  SpectrumD ground_absorbed_below_domain_clamped_W_per_nm{0.0};
  long long lookups = 0;  // Sky lookups made

  SpectrumD powerOut_W_per_nm() const { return diffuse_out_W_per_nm + direct_out_W_per_nm; }
  // (in - out - absorbed) / in, per channel: > 0 when the bake loses light.
  SpectrumD relativeImbalance() const;
};

// The budget of `sky`, every term integrated with the given quadrature
// (OpenMP threads over the sun angles: the lookups must be thread-safe; the
// result does not depend on the thread count).
EnergyBudget computeEnergyBudget(const EnergyBudgetLookups& sky, const EnergyBudgetQuadrature& quadrature = {});
// The same for a bake.
EnergyBudget computeEnergyBudget(const Sky& sky, const EnergyBudgetQuadrature& quadrature = {});

}  // namespace skybake
