// With the sun below the horizon, single scattering is integrated along the
// view ray at each lookup (integrateSingleScattering) instead of read from
// the tables: there the planet's shadow cuts the rays, and where it cuts
// moves fast with the sun's angles, so tables interpolated between texels
// miss it by tens of percent (docs/ERROR_VS_TIME.md). Multiple scattering,
// smooth there, still comes from its table.
#include <algorithm>

#include "runtime/single_scattering_ray.h"
#include "runtime/sky.h"

namespace skybake {
namespace {

// From the horizon up to this sun elevation (as a zenith cosine, sin 1 deg)
// the integral's weight falls smoothly from 1 to 0, so no step shows as the
// sun sets; the tables are within 1 % of the integral there.
constexpr double kIntegratedSingleScatteringTopCosine = 0.0175;
// Sub-intervals of 4 Gauss nodes over the ray for that integral (the bake
// uses 8): 0.12 % RMS of the sky radiance off a 64-sub-interval rule on a
// grid of twilight views, at about 6 times a day lookup's cost
// (docs/MEASUREMENTS.md).
constexpr int kLookupSingleScatteringSegments = 4;

}  // namespace

double Sky::integratedSingleScatteringWeight(double mu_s) {
  const double x = std::clamp(1.0 - mu_s / kIntegratedSingleScatteringTopCosine, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

void Sky::blendInIntegratedSingleScattering(const SunlitRay& ray, double t_start, double t_end, double weight,
                                            SingleScattering& s) const {
  const SingleScattering integrated = integrateSingleScattering(sampler_, bake_.tables.optical_depth, atmosphere(), ray,
                                                                t_start, t_end, kLookupSingleScatteringSegments);
  const float w = static_cast<float>(weight);
  s.rayleigh += (integrated.rayleigh - s.rayleigh) * w;
  s.mie += (integrated.mie - s.mie) * w;
}

}  // namespace skybake
