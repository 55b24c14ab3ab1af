// Single scattering of sunlight along one view ray, integrated from the
// optical-depth table. The bake's table stage computes the same integral
// batched over the suns of a view ray (baker/stages/single_scattering_tables.cpp;
// a test ties the two texel by texel), and lookups with the sun below the
// horizon use it instead of those tables (see Sky). The rule's sub-intervals
// are cut where the ray crosses the edge of the planet's shadow, each part
// with its own Gauss-Legendre rule, so no rule spans the jump where the sun
// appears or disappears, and the integral moves smoothly with the sun
// (forEachOpticallyThinNodeCutAt).
#pragma once

#include <array>
#include <span>
#include <vector>

#include "data_formats/config/atmosphere_parameters.h"
#include "runtime/physics/moon_occluder.h"
#include "runtime/physics/planet_shadow.h"
#include "runtime/tables/table_sampler.h"

namespace skybake {

// Rayleigh and Mie single scattering, each without its phase function.
struct SingleScattering {
  Spectrum rayleigh;
  Spectrum mie;
};

// A view ray in the shell: from radius r at zenith cosine mu, the sun at
// zenith cosine mu_s making cosine nu with the view.
struct SunlitRay {
  double r;
  double mu;
  double mu_s;
  double nu;
  bool ray_intersects_ground;
};

// A colour bake's wavelengths as the integral below needs them: the
// sunlight reaching each point and the view ray's transmittance depend on
// the wavelength, and summing them into X, Y, Z before the product (the
// X, Y, Z atmosphere's effective depths and coefficients) reads twilight
// skies 3 to 20 % off (docs/COLOUR_BAKES.md). Per wavelength group g (of at
// most kMaxChannels wavelengths): its optical-depth table, and for each of
// X, Y, Z what one unit of each lane's integral adds to it: the
// colour-matching weight times the sun's irradiance times the scattering
// coefficient (W m^-2 per unit, Rayleigh and Mie apart).
inline constexpr size_t kMaxWavelengthGroups = kMaxColourWavelengths / kMaxChannels;
struct WavelengthGroupToXyz {
  std::array<SpectrumD, kCieXyzChannels> rayleigh;
  std::array<SpectrumD, kCieXyzChannels> mie;
};
struct ColourWavelengths {
  std::span<const Texture2D> optical_depth;      // per group
  std::span<const WavelengthGroupToXyz> to_xyz;  // per group
};

// Single scattering over [t_start, t_end] of `ray` (metres from its start),
// seen from the ray's start; `segments` is how many sub-intervals of 4
// Gauss nodes [t_start, t_end] gets (optically thick ones split further, see
// ray_quadrature.h), each cut at the shadow's edges inside it. With `moon`,
// the sunlight at each node is also dimmed by the part of the disk the moon
// hides there (an eclipse); its origin, dir and sun_dir must be the 3D form
// of `ray`. With `colour` (a colour bake's wavelengths), the sunlight and
// view-ray transmittance at each node are each wavelength's, from its own
// optical depths, each group's sums weighted into X, Y, Z (at most
// kMaxWavelengthGroups groups); `optical_depth` and `a` (the X, Y, Z
// atmosphere) then only place the nodes.
SingleScattering integrateSingleScattering(const TableSampler& sampler, const Texture2D& optical_depth,
                                           const AtmosphereParameters& a, const SunlitRay& ray, double t_start,
                                           double t_end, int segments, const MoonAlongRay* moon = nullptr,
                                           const ColourWavelengths* colour = nullptr);

// integrateSingleScattering of one view ray (no moon, no colour) under many
// suns: the rule's pieces and their nodes' positions, densities and view-ray
// optical depths are computed once; a sun then adds only its sunlight at
// each node, and recomputes in full only the pieces its shadow's edges cut.
// The same sums as integrateSingleScattering, bit for bit (a test ties
// them), for a hemisphere of directions each under every azimuth of a sun
// (the bake's sky irradiance in twilight).
class SingleScatteringAlongRay {
 public:
  // The view ray (r, mu) over [t_start, t_end], as integrateSingleScattering's.
  SingleScatteringAlongRay(const TableSampler& sampler, const Texture2D& optical_depth, const AtmosphereParameters& a,
                           double r, double mu, bool ray_intersects_ground, double t_start, double t_end, int segments);
  // integrateSingleScattering(sampler, optical_depth, a, {r, mu, mu_s, nu,
  // ray_intersects_ground}, t_start, t_end, segments).
  SingleScattering under(double mu_s, double nu) const;

 private:
  struct Node {
    double t;
    double r_t;
    double rayleigh_weight;  // quadrature weight times density
    double mie_weight;
    Spectrum view_depth;  // optical depth from the ray's start
    TableSampler::SunFromR sun;
  };
  struct Piece {
    double start, end;
    size_t first_node;  // kGaussNodes nodes from here
  };
  const TableSampler& sampler_;
  const Texture2D& optical_depth_;
  const AtmosphereParameters& a_;
  double r_, mu_;
  double t_end_;
  TableSampler::DepthAlongRay view_depth_;  // the view ray's optical depths from its start
  std::vector<Piece> pieces_;
  std::vector<Node> nodes_;

  // The radius at distance t along the ray, kept in the shell.
  double radiusAt(double t) const;
  Node nodeAt(double t, double w) const;
};

// How much of a lookup's single scattering comes from this integral rather
// than the tables, for a sun at zenith cosine mu_s: 1 from the horizon
// down, 0 above kIntegratedSingleScatteringTopCosine
// (sky_lookup_constants.h), a smoothstep between so no step shows as the
// sun sets. The sky lookups and the bake's sky irradiance table weigh the
// two the same way.
double integratedSingleScatteringWeight(double mu_s);

}  // namespace skybake
