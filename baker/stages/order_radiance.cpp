#include "baker/stages/order_radiance.h"

namespace skybake {

Spectrum OrderRadiance::withPhase(const Spectrum& rayleigh_or_multiple, const Spectrum& mie, double nu,
                                  const SpectrumD& peak_weight, double mie_g) const {
  if (order == 1) {
    return rayleigh_or_multiple * static_cast<float>(rayleighPhase(nu)) +
           mie * static_cast<float>(cornetteShanksPhase(mie_g, nu));
  }
  return rayleigh_or_multiple * MultipleScatteringPhase::withPeak(peak_weight, multiple_shape.peakAt(nu));
}

namespace {

// Every nu slice of `table` at the lookup position's (r, mu, mu_s).
void interpolateSlices(const Texture4D& table, const ScatteringCoord& c, Blend blend, std::vector<Spectrum>& slices) {
  const AxisLerp r = axisLerpFromTextureCoord(c.u_r, table.r_size);
  const AxisLerp mu = axisLerpFromTextureCoord(c.u_mu, table.mu_size);
  const AxisLerp mu_s = axisLerpFromTextureCoord(c.u_mu_s, table.mu_s_size);
  slices.resize(static_cast<size_t>(table.nu_size));
  for (int i_nu = 0; i_nu < table.nu_size; ++i_nu) {
    slices[i_nu] = blend == Blend::Linear ? sampleNuSlice<Blend::Linear>(table, r, mu, mu_s, i_nu)
                                          : sampleNuSlice<Blend::GeometricWhereSteep>(table, r, mu, mu_s, i_nu);
  }
}

Spectrum blendSlices(const std::vector<Spectrum>& slices, const AxisLerp& nu, Blend blend) {
  return blendAcross(slices[nu.i0], slices[nu.i1], nu.w1, blend);
}

}  // namespace

void OrderRadianceAlongNu::moveTo(double r, double mu, double mu_s, bool ray_intersects_ground) {
  // (r, mu, mu_s) coordinates do not depend on nu.
  const ScatteringCoord c = sampler_.scatteringCoord(r, mu, mu_s, 0.0, ray_intersects_ground);
  blend_ = radianceBlend(mu_s);
  nu_blend_ = nu_blend_choice_ == NuBlend::Linear ? Blend::Linear : blend_;
  if (order_.order == 1) {
    interpolateSlices(order_.single_rayleigh, c, blend_, rayleigh_or_multiple_);
    interpolateSlices(order_.single_mie, c, blend_, mie_);
  } else {
    interpolateSlices(order_.multiple, c, blend_, rayleigh_or_multiple_);
    peak_weight_ = order_.multiple_shape.peakWeightAt(r - sampler_.domain().bottom_radius_m);
  }
}

Spectrum OrderRadianceAlongNu::at(double nu) const {
  const AxisLerp nu_lerp = axisLerpNu((nu + 1.0) * 0.5, static_cast<int>(rayleigh_or_multiple_.size()));
  const Spectrum mie = order_.order == 1 ? blendSlices(mie_, nu_lerp, nu_blend_) : Spectrum(0.0f);
  return order_.withPhase(blendSlices(rayleigh_or_multiple_, nu_lerp, nu_blend_), mie, nu, peak_weight_, mie_g_);
}

}  // namespace skybake
