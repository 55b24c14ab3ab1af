// The reference: sky radiance, radiance to a point and ground irradiance at a
// single query, computed without any precomputed table, so it is independent
// of the parameterization and of the order-by-order scheme of the bake.
//
// Single scattering (the sun seen through one scattering event, in the air or
// off the ground) is integrated deterministically along the view ray to high
// accuracy. Higher orders are path traced in the spherical shell: vertices
// sampled along each ray, next-event estimation toward the sun's centre
// weighted by the part of its disk above the horizon (runtime/physics/sun_disk.h, the
// bake's own count, so a sun at the horizon is no model mismatch), exact
// optical depths by quadrature of the density profiles, Lambertian ground,
// Rayleigh + Cornette-Shanks Mie + absorption, Russian roulette. Only that
// part (10 to 30 % of the radiance) is noisy, which cuts the noise several
// fold against tracing every order. With the sun below the camera's horizon
// the vertices and directions are drawn partly where the light comes from,
// the sunlit air far from the view ray (LitAirGuide; multiple importance
// sampling, unbiased). Each query has its own fixed seed.
#pragma once

#include <cstdint>
#include <memory>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "data_formats/config/atmosphere_parameters.h"
#include "runtime/physics/moon_occluder.h"

namespace skybake {

class LitAirGuide;

struct ReferenceEstimate {
  SpectrumD value;           // the estimate
  SpectrumD standard_error;  // of the Monte Carlo part (the rest is deterministic)
};

struct ReferenceRay {
  glm::dvec3 camera;  // metres from the planet centre
  glm::dvec3 view;    // unit
  glm::dvec3 sun;     // unit, toward the sun
  double distance_m;  // > 0: up to the point at this distance; else to the ray's end
};

// Whether the reference places its path vertices and directions partly
// where the light comes from (LitAirGuide): for a sun below the horizon of the
// query's camera (the cosine of its zenith angle there below 0), where the
// light scattered more than once comes from sunlit air far from the view
// ray. Daylight queries keep their sampling, and so their values, bit for
// bit; the query keys of the others name the sampling (validation.cpp).
inline bool referenceSamplesTowardLitAir(double camera_sun_zenith_cosine) { return camera_sun_zenith_cosine < 0.0; }

class ReferenceSolver {
 public:
  // Where path vertices go: toward sunlit air for suns below the horizon
  // (the default), or by the density alone for every sun (the daylight
  // estimator everywhere: slower to converge in twilight, kept to check the
  // other against).
  enum class VertexSampling { TowardLitAirBelowHorizon, DensityOnly };
  // `guide`: the guide of this atmosphere to share (its tables fill as
  // paths need them, so solvers made again and again for one atmosphere
  // share one); null: the solver makes its own.
  explicit ReferenceSolver(const AtmosphereParameters& atmosphere,
                           VertexSampling sampling = VertexSampling::TowardLitAirBelowHorizon,
                           std::shared_ptr<LitAirGuide> guide = nullptr);

  // The radiance the viewer receives along the ray, W m^-2 sr^-1 nm^-1:
  // in-scattering of all orders plus, for a ray that ends on the ground (and
  // has no distance limit), the transmitted radiance of the lit Lambertian
  // ground. The direct sun disk is not included. `moon` (none by default)
  // hides part of the sun wherever the sun is connected to: the single
  // scattering quadrature, the lit ground and every next-event estimate, so
  // the paths give the true light inside the moon's shadow. 0 paths give
  // single scattering alone (the deterministic part).
  ReferenceEstimate radiance(const ReferenceRay& ray, int paths, uint64_t seed, const Moon& moon = Moon{}) const;

  // The same estimate of a linear map of the channels, lanes_to_output *
  // radiance (glm's column convention: column c holds what one unit of
  // channel c adds to each output), for a quantity summed over channels
  // such as CIE XYZ. Each path's contribution is mapped before it is
  // averaged, so the standard error counts the channels' correlation (one
  // path serves them all). radiance() is the same estimate unmapped.
  ReferenceEstimate mappedRadiance(const ReferenceRay& ray, int paths, uint64_t seed, const glm::dmat4& lanes_to_output,
                                   const Moon& moon = Moon{}) const;

  // Transmittance along the same segment (exact quadrature, no noise).
  SpectrumD transmittance(const ReferenceRay& ray) const;

  // Sky irradiance (direct sun excluded) on a horizontal surface at `point`.
  ReferenceEstimate skyIrradiance(const glm::dvec3& point, const glm::dvec3& sun, int paths, uint64_t seed,
                                  const Moon& moon = Moon{}) const;
  // Sky irradiance through a linear map of the channels, as mappedRadiance.
  ReferenceEstimate mappedSkyIrradiance(const glm::dvec3& point, const glm::dvec3& sun, int paths, uint64_t seed,
                                        const glm::dmat4& lanes_to_output, const Moon& moon = Moon{}) const;

 private:
  // The guide for a query whose camera sees the sun at this zenith cosine;
  // null for daylight sampling.
  const LitAirGuide* guideFor(double camera_sun_zenith_cosine) const;

  const AtmosphereParameters& a_;
  VertexSampling sampling_;
  // Shared by the solver's copies; its tables fill as paths need them.
  std::shared_ptr<LitAirGuide> guide_;
};

}  // namespace skybake
