// Configs for the analytic test cases.
#pragma once

#include "data_formats/config/config.h"

namespace skybake::test {

// A flat, exponentially stratified, non-absorbing atmosphere of one
// constituent, emulated by a planet of radius 1e8 m with a top 30 scale
// heights up (exp(-30) ~ 1e-13 of the density is cut off). Sun irradiance 1.
inline BakeConfig flatSingleConstituent(bool mie, double scale_height_m) {
  BakeConfig c;
  c.name = mie ? "flat_mie" : "flat_rayleigh";
  AtmosphereParameters& a = c.atmosphere;
  a.wavelengths_nm = {550.0};
  a.bottom_radius_m = 1e8;
  a.top_radius_m = 1e8 + 30.0 * scale_height_m;
  a.sun_irradiance = Spectrum(1.0f, 0, 0, 0);
  a.sun_angular_radius_rad = 0.0;
  const DensityProfile profile = {{0.0, 1.0, -1.0 / scale_height_m, 0.0, 0.0}};
  if (mie) {
    a.mie_scattering = Spectrum(3.996e-6f, 0, 0, 0);
    a.mie_extinction = a.mie_scattering;
    a.mie_phase_g = 0.8;
    a.mie_density = profile;
  } else {
    a.rayleigh_scattering = Spectrum(13.558e-6f, 0, 0, 0);
    a.rayleigh_density = profile;
  }
  return c;
}

// Earth at reduced table sizes: fast enough for tests that bake.
inline BakeConfig smallEarth(int orders) {
  BakeConfig c = builtinEarthConfig();
  c.sizes.transmittance_mu = 64;
  c.sizes.transmittance_r = 16;
  c.sizes.irradiance_mu_s = 16;
  c.sizes.irradiance_r = 8;
  c.sizes.scattering_r = 8;
  c.sizes.scattering_mu = 32;
  c.sizes.scattering_mu_s = 8;
  c.sizes.scattering_nu = 4;
  c.bake.orders = orders;
  return c;
}

// smallEarth with the scattering tables' sizes given.
inline BakeConfig smallEarthWithScattering(int orders, int r, int mu, int mu_s, int nu) {
  BakeConfig c = smallEarth(orders);
  c.sizes.scattering_r = r;
  c.sizes.scattering_mu = mu;
  c.sizes.scattering_mu_s = mu_s;
  c.sizes.scattering_nu = nu;
  return c;
}

}  // namespace skybake::test
