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

#include "runtime/colour/colour_bake_weights.h"
#include "runtime/physics/single_scattering_ray.h"
#include "runtime/sky.h"
#include "runtime/sky_lookup_constants.h"

namespace skybake {

std::vector<WavelengthGroupToXyz> Sky::wavelengthGroupsToXyzOf(const BakeContents& contents) {
  const std::vector<AtmosphereParameters>& groups = contents.wavelength_groups;
  if (groups.empty()) return {};
  const colour::ColourBakeWeights weights(groups);
  std::vector<WavelengthGroupToXyz> to_xyz(groups.size());
  int wavelength = 0;
  for (size_t g = 0; g < groups.size(); ++g) {
    const AtmosphereParameters& a = groups[g];
    for (int l = 0; l < a.channelCount(); ++l, ++wavelength) {
      for (int c = 0; c < kCieXyzChannels; ++c) {
        const double sunlight = weights.colourMatching(c, wavelength) * a.sun_irradiance[l];
        to_xyz[g].rayleigh[c][l] = sunlight * a.rayleigh_scattering[l];
        to_xyz[g].mie[c][l] = sunlight * a.mie_scattering[l];
      }
    }
  }
  return to_xyz;
}

SingleScattering Sky::integratedSingleScattering(const SunlitRay& ray, double t_start, double t_end, int segments,
                                                 const MoonAlongRay* moon) const {
  const ColourWavelengths colour{bake_.wavelength_optical_depth, wavelength_groups_to_xyz_};
  return integrateSingleScattering(sampler_, bake_.tables.optical_depth, atmosphere(), ray, t_start, t_end, segments,
                                   moon, wavelength_groups_to_xyz_.empty() ? nullptr : &colour);
}

void Sky::blendInIntegratedSingleScattering(const SunlitRay& ray, double t_start, double t_end, double weight,
                                            SingleScattering& s) const {
  const SingleScattering integrated = integratedSingleScattering(ray, t_start, t_end, kLookupSingleScatteringSegments);
  const float w = static_cast<float>(weight);
  s.rayleigh += (integrated.rayleigh - s.rayleigh) * w;
  s.mie += (integrated.mie - s.mie) * w;
}

}  // namespace skybake
