// Names shared by the bake-file writer and reader (FORMAT.md lists them).
#pragma once

namespace skybake::bake_file {

inline constexpr const char* kPartTransmittance = "transmittance";
inline constexpr const char* kPartSingleRayleigh = "single_rayleigh";
inline constexpr const char* kPartSingleMie = "single_mie";
inline constexpr const char* kPartMultipleScattering = "multiple_scattering";
inline constexpr const char* kPartIrradiance = "irradiance";
inline constexpr const char* kPartMultipleDensity = "multiple_scattering_density";

inline constexpr const char* kAttrFormatVersion = "skybake:format_version";
inline constexpr const char* kAttrConfig = "skybake:config";
inline constexpr const char* kAttrOrders = "skybake:orders";
inline constexpr const char* kAttrBakeReport = "skybake:bake_report";
inline constexpr const char* kAttrContent = "skybake:content";
inline constexpr const char* kAttrUnits = "skybake:units";
inline constexpr const char* kAttrWavelengths = "skybake:wavelengths_nm";
inline constexpr const char* kAttrBottomRadius = "skybake:bottom_radius_m";
inline constexpr const char* kAttrTopRadius = "skybake:top_radius_m";
inline constexpr const char* kAttrMuSMin = "skybake:mu_s_min";
inline constexpr const char* kAttrScatteringRRange = "skybake:scattering_r_range_m";
inline constexpr const char* kAttrScatteringMuSRange = "skybake:scattering_mu_s_range";
inline constexpr const char* kAttrTableSize = "skybake:table_size";

}  // namespace skybake::bake_file
