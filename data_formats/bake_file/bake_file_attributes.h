// Names shared by the bake-file writer and reader (FORMAT.md lists them).
#pragma once

namespace skybake::bake_file {

inline constexpr const char* kPartOpticalDepth = "optical_depth";
inline constexpr const char* kPartSingleRayleigh = "single_rayleigh";
inline constexpr const char* kPartSingleMie = "single_mie";
inline constexpr const char* kPartMultipleScattering = "multiple_scattering";
inline constexpr const char* kPartIrradiance = "irradiance";
inline constexpr const char* kPartMultipleDensity = "multiple_scattering_density";
// Version 10: a colour bake's optical depth per wavelength, one channel each.
inline constexpr const char* kPartWavelengthOpticalDepth = "wavelength_optical_depth";
// Version 2's name of the optical-depth part.
inline constexpr const char* kPartOpticalDepthVersion2 = "transmittance";

inline constexpr const char* kAttrFormatVersion = "skybake:format_version";
inline constexpr const char* kAttrConfig = "skybake:config";
inline constexpr const char* kAttrOrders = "skybake:orders";
inline constexpr const char* kAttrBakeReport = "skybake:bake_report";
inline constexpr const char* kAttrContent = "skybake:content";
inline constexpr const char* kAttrUnits = "skybake:units";
inline constexpr const char* kAttrTableSize = "skybake:table_size";

// The atmosphere (version 3): one attribute per parameter, named as its config key.
inline constexpr const char* kAttrWavelengths = "skybake:wavelengths_nm";
// Version 4: what the channels hold, "wavelengths" (one per entry of
// skybake:wavelengths_nm) or "cie_xyz" (X, Y, Z integrated over them).
inline constexpr const char* kAttrChannels = "skybake:channels";
inline constexpr const char* kAttrBottomRadius = "skybake:bottom_radius_m";
inline constexpr const char* kAttrTopRadius = "skybake:top_radius_m";
inline constexpr const char* kAttrGroundAlbedo = "skybake:ground_albedo";
inline constexpr const char* kAttrSunIrradiance = "skybake:sun_irradiance";
inline constexpr const char* kAttrSunAngularRadius = "skybake:sun_angular_radius_rad";
inline constexpr const char* kAttrSunMaxZenith = "skybake:sun_max_zenith_deg";
inline constexpr const char* kAttrRayleighScattering = "skybake:rayleigh_scattering";
inline constexpr const char* kAttrRayleighDensity = "skybake:rayleigh_density";
inline constexpr const char* kAttrMieScattering = "skybake:mie_scattering";
inline constexpr const char* kAttrMieExtinction = "skybake:mie_extinction";
inline constexpr const char* kAttrMiePhaseG = "skybake:mie_phase_g";
inline constexpr const char* kAttrMieDensity = "skybake:mie_density";
inline constexpr const char* kAttrAbsorptionExtinction = "skybake:absorption_extinction";
inline constexpr const char* kAttrAbsorptionDensity = "skybake:absorption_density";
// Version 10, colour bakes: each wavelength's own values of the per-channel
// quantities above, in skybake:wavelengths_nm's order.
inline constexpr const char* kAttrWavelengthGroundAlbedo = "skybake:wavelength_ground_albedo";
inline constexpr const char* kAttrWavelengthSunIrradiance = "skybake:wavelength_sun_irradiance";
inline constexpr const char* kAttrWavelengthRayleighScattering = "skybake:wavelength_rayleigh_scattering";
inline constexpr const char* kAttrWavelengthMieScattering = "skybake:wavelength_mie_scattering";
inline constexpr const char* kAttrWavelengthMieExtinction = "skybake:wavelength_mie_extinction";
inline constexpr const char* kAttrWavelengthAbsorptionExtinction = "skybake:wavelength_absorption_extinction";

// The tables' sizes and what they hold (version 3).
inline constexpr const char* kAttrOpticalDepthSize = "skybake:optical_depth_size";
inline constexpr const char* kAttrIrradianceSize = "skybake:irradiance_size";
inline constexpr const char* kAttrScatteringSizeRMu = "skybake:scattering_size_r_mu";
inline constexpr const char* kAttrScatteringSizeMuSNu = "skybake:scattering_size_mu_s_nu";
// Version 7: the density part's view (mu) texels (BakeContents::density_view_size).
inline constexpr const char* kAttrDensityViewSize = "skybake:density_view_size";
inline constexpr const char* kAttrOutputs = "skybake:outputs";
inline constexpr const char* kAttrCombinedSingleMie = "skybake:combined_single_mie";
// The fraction bits every FLOAT value but the optical depths' keeps
// (stored_float_bits.h); absent: all 23.
// A HALF 4D part's power-of-two exponent per (r, mu_s) slice (half_slices.h),
// index r * mu_s_size + mu_s: a value is its half times 2^exponent.
inline constexpr const char* kAttrHalfSliceExponents = "skybake:half_slice_exponents";
inline constexpr const char* kAttrStoredFractionBits = "skybake:stored_fraction_bits";

// The domain the 4D tables cover.
inline constexpr const char* kAttrMuSMin = "skybake:mu_s_min";
inline constexpr const char* kAttrScatteringRRange = "skybake:scattering_r_range_m";
inline constexpr const char* kAttrScatteringMuSRange = "skybake:scattering_mu_s_range";
// Version 3: the same ends in the parameterization's own coordinates, exactly.
inline constexpr const char* kAttrScatteringRhoRange = "skybake:scattering_rho_range_m";
inline constexpr const char* kAttrScatteringMuSCoordRange = "skybake:scattering_mu_s_coord_range";
inline constexpr const char* kAttrScatteringGroundViews = "skybake:scattering_ground_views";

}  // namespace skybake::bake_file
