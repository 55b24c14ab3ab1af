// Where the light that reaches a point in twilight comes from: a proposal
// for the reference's paths with the sun below the horizon.
//
// In deep twilight the air near a viewer lies in the planet's shadow and all
// its light comes from sunlit air hundreds of kilometres away, seen from
// each point in a narrow band of directions a few degrees above its horizon
// toward the sun, and more of it the higher the point. The guide tabulates,
// for points at a grid of altitudes and sun zenith angles, the radiance
// arriving from each direction, scattered once on its way from the sun and,
// taken as isotropic there, scattered a second time (in deep twilight blue
// light near the ground has mostly come down from shadowed air higher up,
// lit by sunlit air the ground does not see), by coarse quadrature along
// each direction's ray. The reference draws the next direction of a path
// from it, and places vertices along a ray by how much light arrives there.
// It is only a proposal: the estimates divide by its exact density, so they
// stay unbiased whatever its accuracy, and it only moves where the paths go.
//
// By the atmosphere's spherical symmetry and the sun's parallel rays, the
// light arriving at a point depends only on its altitude and the sun's
// zenith angle there, and directions only on elevation and azimuth from the
// sun's (mirror symmetric). Each cell of that grid is computed the first
// time a path needs it (thread-safe) and kept for the guide's lifetime.
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <vector>

#include <glm/vec3.hpp>

#include "data_formats/config/atmosphere_parameters.h"
#include "runtime/physics/atmosphere_media.h"

namespace skybake {

class LitAirGuide {
 public:
  explicit LitAirGuide(const AtmosphereParameters& atmosphere);
  ~LitAirGuide();
  LitAirGuide(const LitAirGuide&) = delete;
  LitAirGuide& operator=(const LitAirGuide&) = delete;

  struct Cell;
  // What the guide knows at one point: the grid cells around it (bilinear in
  // altitude and sun zenith angle) and the point's frame.
  struct Site {
    std::array<const Cell*, 4> cell{};
    std::array<double, 4> weight{};         // bilinear, summing to 1
    std::array<double, 4> sample_weight{};  // over the cells with a direction table; all 0: none
    glm::dvec3 up, sunward, side;           // sunward: horizontal, toward the sun's azimuth
  };
  Site siteAt(const glm::dvec3& point, const glm::dvec3& sun) const;

  // The mean over all directions of the radiance scattered once or twice
  // that arrives at the site, per channel (W m^-2 sr^-1 nm^-1), as the
  // tables have it.
  SpectrumD meanInscatteredRadiance(const Site& site) const;

  // Whether the site has directions to propose (some sunlit air in view).
  static bool proposesDirections(const Site& site) {
    return site.sample_weight[0] + site.sample_weight[1] + site.sample_weight[2] + site.sample_weight[3] > 0.0;
  }
  // A direction from two uniform numbers, and the density (per steradian)
  // that it is drawn with; only where proposesDirections.
  glm::dvec3 sampleDirection(const Site& site, double u_elevation, double u_azimuth) const;
  double directionPdf(const Site& site, const glm::dvec3& dir) const;

  // The sun's transmittance at a point (0 where its centre is below the
  // point's horizon), from a coarse table: for proposals only.
  SpectrumD sunTransmittance(const glm::dvec3& point, const glm::dvec3& sun) const;

 private:
  // Where a point lies on the grid: the lower corner of its cell and the
  // bilinear weights of the four corners (altitude fastest).
  struct GridPosition {
    int altitude_index = 0, sun_index = 0;
    std::array<double, 4> weight{};
    double sun_up = 0.0;  // the sun's zenith cosine at the point
  };
  GridPosition gridPosition(const glm::dvec3& point, const glm::dvec3& sun) const;
  template <typename SourceFn>
  SpectrumD alongRay(const glm::dvec3& point, const glm::dvec3& dir, SourceFn&& source) const;
  void computeOnceScattered(Cell& cell, int altitude_index, int sun_index) const;
  void computeTwiceScattered(Cell& cell) const;
  SpectrumD onceScatteredMeanRadiance(const glm::dvec3& point, const glm::dvec3& sun) const;
  Cell& onceScatteredCell(int altitude_index, int sun_index) const;
  const Cell& cellAt(int altitude_index, int sun_index) const;
  double sunDepthCoordinate(double r, double mu_s, double& mu_horizon) const;

  const AtmosphereParameters a_;  // a copy: a guide may outlive the solver that made it
  AtmosphereMedia media_;
  // Optical depth to the top toward the sun, [radius row][sun column],
  // computed on first use.
  mutable std::once_flag sun_depth_once_;
  mutable std::vector<SpectrumD> sun_depth_;
  std::unique_ptr<Cell[]> cells_;
};

}  // namespace skybake
