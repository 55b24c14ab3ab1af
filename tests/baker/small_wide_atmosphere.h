// The small Earth of the colour and spectral bake tests, everything after
// its [channels] table: spectra from laws and inline tables over 380 to
// 780 nm (no files), so any set of wavelengths there is the same
// atmosphere; a sun that varies, so that sunlight weights differ from the
// colour-matching ones; a coloured ozone and ground; tables small enough
// to bake in about a second. It ends in [bake] (3 orders), so a caller may
// add more [bake] keys after it.
#pragma once

#include <string_view>

namespace skybake {

inline constexpr std::string_view kSmallWideAtmosphereToml = R"([planet]
bottom_radius_m = 6360000.0
top_radius_m = 6420000.0
ground_albedo = { wavelengths_nm = [380, 780], values = [0.05, 0.3] }
[sun]
irradiance = { wavelengths_nm = [380, 450, 550, 780], values = [1.1, 2.0, 1.85, 1.2] }
[rayleigh]
scattering = { at_nm = 550, value = 13.558e-6, exponent = 4 }
density = [{ exp_term = 1.0, exp_scale = -1.25e-4 }]
[mie]
scattering = { at_nm = 550, value = 3.996e-6, angstrom_exponent = 1.3 }
extinction = { at_nm = 550, value = 4.44e-6, angstrom_exponent = 1.3 }
phase_g = 0.8
density = [{ exp_term = 1.0, exp_scale = -8.333e-4 }]
[absorption]
extinction = { wavelengths_nm = [380, 600, 780], values = [1e-8, 2.5e-6, 1.5e-7] }
density = [{ width_m = 25000.0, linear_term = 6.667e-5, constant_term = -0.6667 },
           { linear_term = -6.667e-5, constant_term = 2.6667 }]
[resolution]
transmittance = [64, 16]
irradiance = [16, 8]
scattering = { r = 8, mu = 32, mu_s = 8, nu = 4 }
[bake]
orders = 3
)";

}  // namespace skybake
