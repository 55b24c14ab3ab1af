// Sky::skyRadianceBatch: many view directions from one camera under one sun.
// With the camera fixed, r and mu_s are the same for every ray, so the 4D
// tables are interpolated in (r, mu_s) once per call into 2D (mu, nu) slices,
// and each ray then needs 4 texels per table instead of 16. The transmittance
// table is reduced the same way to the rows at r and at the ground.
#include <glm/geometric.hpp>

#include "runtime/sky.h"

namespace skybake {
namespace {

// A 4D table interpolated at one (r, mu_s): mu_size x nu_size texels.
struct MuNuSlice {
  int mu_size = 0;
  int nu_size = 0;
  Blend blend = Blend::Linear;
  std::vector<Spectrum> texels;  // [i_mu * nu_size + i_nu]

  MuNuSlice() = default;
  MuNuSlice(const Texture4D& t, const AxisLerp& r, const AxisLerp& mu_s, Blend blend)
      : mu_size(t.mu_size), nu_size(t.nu_size), blend(blend), texels(static_cast<size_t>(t.mu_size) * t.nu_size) {
    // Same multilinear weights as sample4D, applied in a different order.
    for (int i_mu = 0; i_mu < mu_size; ++i_mu) {
      for (int i_nu = 0; i_nu < nu_size; ++i_nu) {
        auto row = [&](int i_r) {
          return blendAcross(t.at(i_r, i_mu, mu_s.i0, i_nu), t.at(i_r, i_mu, mu_s.i1, i_nu), mu_s.w1, blend);
        };
        const Spectrum r0 = row(r.i0);
        texels[static_cast<size_t>(i_mu) * nu_size + i_nu] = r0 + (row(r.i1) - r0) * r.w1;
      }
    }
  }

  // A slice of zeros of `t`'s mu and nu sizes.
  static MuNuSlice zeros(const Texture4D& t, Blend blend) {
    MuNuSlice s;
    s.mu_size = t.mu_size;
    s.nu_size = t.nu_size;
    s.blend = blend;
    s.texels.assign(static_cast<size_t>(t.mu_size) * t.nu_size, Spectrum(0.0f));
    return s;
  }

  Spectrum sample(const AxisLerp& mu, const AxisLerp& nu) const {
    auto at = [&](int i_mu, int i_nu) -> const Spectrum& { return texels[static_cast<size_t>(i_mu) * nu_size + i_nu]; };
    const Spectrum a = at(mu.i0, nu.i0) + (at(mu.i1, nu.i0) - at(mu.i0, nu.i0)) * mu.w1;
    const Spectrum b = at(mu.i0, nu.i1) + (at(mu.i1, nu.i1) - at(mu.i0, nu.i1)) * mu.w1;
    return blendAcross(a, b, nu.w1, blend);
  }
};

// One row of the optical-depth table, interpolated at one r.
struct OpticalDepthRow {
  std::vector<Spectrum> texels;
  OpticalDepthRow(const Texture2D& t, const AxisLerp& r) : texels(t.width) {
    for (int i = 0; i < t.width; ++i) texels[i] = t.at(i, r.i0) + (t.at(i, r.i1) - t.at(i, r.i0)) * r.w1;
  }
  Spectrum sample(double u) const {
    const AxisLerp x = axisLerpFromTextureCoord(u, static_cast<int>(texels.size()));
    return texels[x.i0] + (texels[x.i1] - texels[x.i0]) * x.w1;
  }
};

}  // namespace

void Sky::skyRadianceBatch(const glm::dvec3& camera, const glm::dvec3& sun_dir, const ViewRayBatch& rays,
                           SpectrumBatch radiance, SpectrumBatch transmittance) const {
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
      const RadianceAndTransmittance v =
          skyRadiance(camera, glm::dvec3(rays.dir_x[i], rays.dir_y[i], rays.dir_z[i]), sun_dir);
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
  const TextureSizes& sizes = sampler_.sizes();
  const ScatteringSizes& ss = sampler_.scatteringSizes();
  const BakeTables& t = bake_.tables;

  const AxisLerp r_lerp = axisLerpFromTextureCoord(scatteringCoordR(d, ss.r, rho), ss.r);
  const AxisLerp mu_s_lerp = axisLerpFromTextureCoord(scatteringCoordMuS(d, ss.mu_s, mu_s), ss.mu_s);
  const MuNuSlice rayleigh(t.single_rayleigh, r_lerp, mu_s_lerp, radianceBlend(mu_s));
  // Without Mie scattering the bake stores no single Mie table: a slice of zeros.
  const MuNuSlice mie = hasSingleMie() ? MuNuSlice(t.single_mie, r_lerp, mu_s_lerp, radianceBlend(mu_s))
                                       : MuNuSlice::zeros(t.single_rayleigh, radianceBlend(mu_s));
  const MuNuSlice multiple(t.multiple_scattering, r_lerp, mu_s_lerp, radianceBlend(mu_s));
  const SpectrumD multiple_peak_weight = multiple_shape_.peakWeightAt(r - d.bottom_radius_m);
  const OpticalDepthRow depth_here(
      t.optical_depth, axisLerpFromTextureCoord(textureCoordFromUnitRange(rho / H, sizes.transmittance_r),
                                                sizes.transmittance_r));
  const OpticalDepthRow depth_ground(t.optical_depth, axisLerpFromTextureCoord(
                                                          textureCoordFromUnitRange(0.0, sizes.transmittance_r),
                                                          sizes.transmittance_r));
  const double g = atmosphere().mie_phase_g;
  const int channels = channelCount();
  // Cornette-Shanks without the per-call normalisation: 1 + g^2 and the constant.
  const double cs_norm = 3.0 / (8.0 * kPi) * (1.0 - g * g) / (2.0 + g * g);
  const double one_plus_g2 = 1.0 + g * g;

  for (size_t i = 0; i < rays.count; ++i) {
    const glm::dvec3 dir(rays.dir_x[i], rays.dir_y[i], rays.dir_z[i]);
    const double mu = clampCosine(glm::dot(up, dir));
    const double nu = clampCosine(glm::dot(dir, sun_dir));
    const bool ground = rayIntersectsSphere(r, mu, d.bottom_radius_m);
    if (ground && !d.scattering_ground_views) {
      // The tables hold no rays toward the ground: integrated, as skyRadiance does.
      const RadianceAndTransmittance v = skyRadiance(camera, dir, sun_dir);
      store(i, v.radiance, v.transmittance);
      continue;
    }
    const AxisLerp mu_lerp = axisLerpFromTextureCoord(scatteringCoordMu(d, ss.mu, r, rho, H, mu, ground), ss.mu);
    const AxisLerp nu_lerp = axisLerpNu((nu + 1.0) * 0.5, ss.nu);
    const double base = one_plus_g2 - 2.0 * g * nu;
    const double mie_phase = cs_norm * (1.0 + nu * nu) / (base * std::sqrt(base));
    const SingleScattering single =
        singleScattering({r, mu, mu_s, nu, ground}, 0.0,
                         distanceToAtmosphereEnd(r, mu, d.bottom_radius_m, d.top_radius_m, ground), [&] {
                           return SingleScattering{rayleigh.sample(mu_lerp, nu_lerp), mie.sample(mu_lerp, nu_lerp)};
                         });
    const Spectrum l = single.rayleigh * static_cast<float>(rayleighPhase(nu)) +
                       single.mie * static_cast<float>(mie_phase) +
                       multiple.sample(mu_lerp, nu_lerp) * multiple_shape_(multiple_peak_weight, nu);
    Spectrum tau;
    if (ground) {
      // Both legs reversed (pointing up), as TableSampler::opticalDepthAlongRay.
      const double to_ground = distanceToInnerSphere(r, mu, d.bottom_radius_m);
      const double mu_ground = cosineAlongRay(r, mu, to_ground, d.bottom_radius_m);
      tau = glm::max(depth_ground.sample(transmittanceCoordMu(d, sizes.transmittance_mu, d.bottom_radius_m, 0.0, H, -mu_ground)) -
                         depth_here.sample(transmittanceCoordMu(d, sizes.transmittance_mu, r, rho, H, -mu)),
                     Spectrum(0.0f));
    } else {
      tau = depth_here.sample(transmittanceCoordMu(d, sizes.transmittance_mu, r, rho, H, mu));
    }
    Spectrum t_out(0.0f);
    for (int c = 0; c < channels; ++c) t_out[c] = std::exp(-tau[c]);  // unused lanes stay 0
    store(i, l, t_out);
  }
}

}  // namespace skybake
