// Photometric quantities from the CIE Y of a spectral radiometric one.
#pragma once

namespace skybake::colour {

// The maximum luminous efficacy of photopic vision, K_m = 683 lm/W (CIE
// 015:2018; the SI's definition of the candela fixes 683 lm/W at 540 THz,
// where V(lambda) is 1 to within 2e-5).
inline constexpr double kMaxLuminousEfficacy_lm_per_W = 683.0;

// Luminance (cd m^-2 = lm m^-2 sr^-1) from Y of spectral radiance in
// W m^-2 sr^-1 nm^-1 (SpectralToXyz: Y in W m^-2 sr^-1).
inline double luminance_cd_m2(double y_W_m2_sr) { return kMaxLuminousEfficacy_lm_per_W * y_W_m2_sr; }

// Illuminance (lx = lm m^-2) from Y of spectral irradiance in W m^-2 nm^-1.
inline double illuminance_lx(double y_W_m2) { return kMaxLuminousEfficacy_lm_per_W * y_W_m2; }

}  // namespace skybake::colour
