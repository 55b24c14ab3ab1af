#include "baker/stages.h"

namespace skybake {

Spectrum OrderRadiance::radiance(const TableSampler& sampler, double r, double mu, double mu_s,
                                 double nu, bool ray_intersects_ground, double mie_g) const {
  if (order == 1) {
    return sampler.scattering(single_rayleigh, r, mu, mu_s, nu, ray_intersects_ground) *
               static_cast<float>(rayleighPhase(nu)) +
           sampler.scattering(single_mie, r, mu, mu_s, nu, ray_intersects_ground) *
               static_cast<float>(cornetteShanksPhase(mie_g, nu));
  }
  return sampler.scattering(multiple, r, mu, mu_s, nu, ray_intersects_ground) *
         multiple_shape(r - sampler.domain().bottom_radius_m, nu);
}

}  // namespace skybake
