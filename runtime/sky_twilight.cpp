// With the sun below the horizon, single scattering is integrated along the
// view ray at each lookup (integrateSingleScattering) instead of read from
// the tables: there the planet's shadow cuts the rays, and where it cuts
// moves fast with the sun's angles, so tables interpolated between texels
// miss it by tens of percent (docs/MEASUREMENTS.md). The integral needs no
// table of suns, so it is evaluated for the sun where it is, below the
// lowest baked sun too (a narrowed scene's tables aside: Sky::withBakedSun).
// Multiple scattering, smooth there, still comes from its table, continued
// below the lowest baked sun by runtime/night_sky.h.
#include <algorithm>

#include "runtime/physics/single_scattering_ray.h"
#include "runtime/sky.h"
#include "runtime/sky_lookup_constants.h"

namespace skybake {

void Sky::blendInIntegratedSingleScattering(const SunlitRay& ray, double t_start, double t_end, double weight,
                                            SingleScattering& s) const {
  const SingleScattering integrated = integrateSingleScattering(sampler_, bake_.tables.optical_depth, atmosphere(), ray,
                                                                t_start, t_end, kLookupSingleScatteringSegments);
  const float w = static_cast<float>(weight);
  s.rayleigh += (integrated.rayleigh - s.rayleigh) * w;
  s.mie += (integrated.mie - s.mie) * w;
}

}  // namespace skybake
