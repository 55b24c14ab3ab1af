// Sky::skyRadianceBatch: many view directions from one camera under one sun.
// With the camera fixed, r and mu_s are the same for every ray, so the 4D
// tables are interpolated in (r, mu_s) once per call into 2D (mu, nu) slices,
// and each ray then needs 4 texels per table instead of 16. Both steps, and
// the optical depths, use the scalar lookups' own sampling functions.
#include <glm/geometric.hpp>

#include "runtime/lookup_geometry.h"
#include "runtime/sky.h"

namespace skybake {
namespace {

// A 4D table interpolated at one (r, mu_s), as a table of one r and one mu_s
// texel (mu_size x nu_size), so that rays then read it through sample4D like
// any table: each nu slice texel is sampleNuSlice's blend at that (r, mu_s).
Texture4D sliceAt(const Texture4D& t, const AxisLerp& r, const AxisLerp& mu_s, Blend blend) {
  Texture4D slice(1, t.mu_size, 1, t.nu_size);
  for (int i_mu = 0; i_mu < t.mu_size; ++i_mu) {
    const AxisLerp mu{i_mu, i_mu, 0.0f};
    for (int i_nu = 0; i_nu < t.nu_size; ++i_nu) {
      slice.at(0, i_mu, 0, i_nu) = blend == Blend::Linear
                                       ? sampleNuSlice<Blend::Linear>(t, r, mu, mu_s, i_nu)
                                       : sampleNuSlice<Blend::GeometricWhereSteep>(t, r, mu, mu_s, i_nu);
    }
  }
  return slice;
}

// Ray i's direction, checked and normalised as every lookup's (lookup_geometry.h).
glm::dvec3 rayDirection(const ViewRayBatch& rays, size_t i) {
  return lookupDirection(glm::dvec3(rays.dir_x[i], rays.dir_y[i], rays.dir_z[i]), "view direction");
}

Spectrum sampleSlice(const Texture4D& slice, const AxisLerp& mu, const AxisLerp& nu, Blend blend) {
  return blend == Blend::Linear ? sampleMuNuSlice<Blend::Linear>(slice, mu, nu)
                                : sampleMuNuSlice<Blend::GeometricWhereSteep>(slice, mu, nu);
}

}  // namespace

void Sky::skyRadianceBatch(const glm::dvec3& camera_given, const glm::dvec3& sun_dir_given, const ViewRayBatch& rays,
                           SpectrumBatch radiance, SpectrumBatch transmittance) const {
  requireOneLaneGroup("skyRadianceBatch");
  const glm::dvec3 camera = lookupPosition(camera_given, "camera");
  const glm::dvec3 sun_dir = lookupDirection(sun_dir_given, "sun direction");
  auto store = [&](size_t i, const Spectrum& l, const Spectrum& t) {
    for (int c = 0; c < channelCount(); ++c) {
      if (radiance.channel[c] != nullptr) radiance.channel[c][i] = l[c];
      if (transmittance.channel[c] != nullptr) transmittance.channel[c][i] = t[c];
    }
  };
  const AtmosphereDomain& d = sampler_.domain();
  const double length = glm::length(camera);
  if (!(length <= d.top_radius_m)) {
    // In space every ray enters at its own point: no shared (r, mu_s).
    for (size_t i = 0; i < rays.count; ++i) {
      const RadianceAndTransmittance v = skyRadiance(camera, rayDirection(rays, i), sun_dir);
      store(i, v.radiance, v.transmittance);
    }
    return;
  }
  // Below the ground: on the ground directly above (as skyRadiance does).
  const double r = std::max(length, d.bottom_radius_m);
  const glm::dvec3 up = length > 0.0 ? camera / length : glm::dvec3(0.0, 0.0, 1.0);
  const double mu_s = clampCosine(glm::dot(up, sun_dir));
  const double H = d.horizonToTopDistance();
  const double rho = d.distanceToHorizon(r);
  const ScatteringSizes& ss = sampler_.scatteringSizes();
  const BakeTables& t = bake_.tables;

  const AxisLerp r_lerp = axisLerpFromTextureCoord(scatteringCoordR(d, ss.r, rho), ss.r);
  const AxisLerp mu_s_lerp = axisLerpFromTextureCoord(scatteringCoordMuS(d, ss.mu_s, mu_s), ss.mu_s);
  const Blend blend = radianceBlend(mu_s);
  const Texture4D rayleigh = sliceAt(t.single_rayleigh, r_lerp, mu_s_lerp, blend);
  // Without Mie scattering the bake stores no single Mie table: a slice of zeros.
  const Texture4D mie =
      hasSingleMie() ? sliceAt(t.single_mie, r_lerp, mu_s_lerp, blend) : Texture4D(1, ss.mu, 1, ss.nu);
  const Texture4D multiple = sliceAt(t.multiple_scattering, r_lerp, mu_s_lerp, blend);
  // Below the lowest baked sun the slices hold that sun's values (the
  // coordinate clamps): scaled as TableSampler::scattering scales them.
  const Spectrum night = sampler_.nightScale4D(mu_s);
  const SpectrumD multiple_peak_weight = multiple_shape_.peakWeightAt(r - d.bottom_radius_m);
  const int channels = channelCount();
  const TableSampler::OpticalDepthFromR depth_here(sampler_, r), depth_at_ground(sampler_, d.bottom_radius_m);

  for (size_t i = 0; i < rays.count; ++i) {
    const glm::dvec3 dir = rayDirection(rays, i);
    const double mu = clampCosine(glm::dot(up, dir));
    const double nu = clampCosine(glm::dot(dir, sun_dir));
    const bool ground = rayIntersectsSphere(r, mu, d.bottom_radius_m);
    if (ground && !d.scattering_ground_views) {
      // The tables hold no rays toward the ground: integrated, as skyRadiance does.
      const RadianceAndTransmittance v = skyRadiance(camera, dir, sun_dir);
      store(i, v.radiance, v.transmittance);
      continue;
    }
    const double end_m = distanceToAtmosphereEnd(r, mu, d.bottom_radius_m, d.top_radius_m, ground);
    const AxisLerp mu_lerp =
        axisLerpFromTextureCoord(scatteringCoordMuAtDistance(d, ss.mu, r, rho, H, end_m, ground), ss.mu);
    const AxisLerp nu_lerp = axisLerpNu(kernel::skybakeScatteringCoordNu(nu), ss.nu);
    const SingleScattering single = singleScattering({r, mu, mu_s, nu, ground}, 0.0, end_m, mu_s, [&] {
      return SingleScattering{sampleSlice(rayleigh, mu_lerp, nu_lerp, blend) * night,
                              sampleSlice(mie, mu_lerp, nu_lerp, blend) * night};
    });
    const Spectrum l =
        single.rayleigh * static_cast<float>(rayleighPhase(nu)) + single.mie * static_cast<float>(mie_phase_(nu)) +
        sampleSlice(multiple, mu_lerp, nu_lerp, blend) * night * multiple_shape_(multiple_peak_weight, nu);
    // As TableSampler::opticalDepthAlongRay takes a ray to the ground: both legs reversed.
    // end_m is the distance to the ground or to the top.
    const Spectrum tau =
        ground ? TableSampler::depthBetween(
                     depth_at_ground.toTop(t.optical_depth, -cosineAlongRay(r, mu, end_m, d.bottom_radius_m)),
                     depth_here.toTop(t.optical_depth, -mu))
               : depth_here.opticalDepth(t.optical_depth, depth_here.muCoordAtDistance(end_m));
    Spectrum t_out(0.0f);
    for (int c = 0; c < channels; ++c) t_out[c] = std::exp(-tau[c]);  // unused lanes stay 0
    store(i, l, t_out);
  }
}

}  // namespace skybake
