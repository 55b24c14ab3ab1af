#include "runtime/gl/sky_gl_parameters.h"

#include <cmath>

#include <glm/geometric.hpp>

#include <fmt/format.h>

#include "data_formats/error.h"
#include "runtime/physics/atmosphere_media.h"
#include "runtime/physics/eclipse_skylight.h"
#include "runtime/physics/ray_quadrature.h"
#include "runtime/sky_lookup_constants.h"

namespace skybake::gl {

extern const std::string_view kGlslLibrarySource;

namespace {

// A GLSL float literal: always with an exponent, so ES 3.00 (no implicit
// int-to-float conversion) never reads it as an int.
std::string glslFloat(double value) { return fmt::format("{:.9e}", value); }

void put(float (&out)[4], const Spectrum& s) {
  for (int c = 0; c < 4; ++c) out[c] = s[c];
}

void putLayers(SkyUniformBlock& block, int profile, const DensityProfile& layers, const char* name) {
  if (static_cast<int>(layers.size()) > kMaxGlDensityLayers) {
    throw Error(ErrorKind::BadInput,
                fmt::format("the GL backend holds at most {} density layers, the {} profile has {}",
                            kMaxGlDensityLayers, name, layers.size()));
  }
  block.profile_layers[profile] = static_cast<int32_t>(layers.size());
  for (size_t i = 0; i < layers.size(); ++i) {
    const int at = profile * kMaxGlDensityLayers + static_cast<int>(i);
    const DensityLayer& l = layers[i];
    block.layer_shape[at][0] = static_cast<float>(l.width_m);
    block.layer_shape[at][1] = static_cast<float>(l.exp_term);
    block.layer_shape[at][2] = static_cast<float>(l.exp_scale);
    block.layer_shape[at][3] = static_cast<float>(l.linear_term);
    block.layer_constant[at][0] = static_cast<float>(l.constant_term);
  }
}

// m_column^2 of the multiple-scattering shape (thinned, as the bake's
// MultipleShapeWeight says), per channel: its peak weight
// at an altitude where Mie scatters, over Mie's local share there (the
// shape keeps the column share to itself). Where no altitude has Mie
// scattering the weight is 0 everywhere and so is this.
Spectrum columnMieSharePower(const Sky& sky, const MultipleScatteringPhase& shape) {
  const AtmosphereParameters& a = sky.atmosphere();
  const AtmosphereMedia media(a);
  constexpr int kProbeAltitudes = 64;  // any altitude with Mie serves; the first found is used
  Spectrum power(0.0f);
  for (int c = 0; c < kMaxChannels; ++c) {
    for (int i = 0; i < kProbeAltitudes; ++i) {
      const double altitude_m = (a.top_radius_m - a.bottom_radius_m) * i / kProbeAltitudes;
      const double rayleigh = a.rayleigh_scattering[c] * media.rayleighDensity(altitude_m);
      const double mie = a.mie_scattering[c] * media.mieDensity(altitude_m);
      if (!(mie > 0.0)) continue;
      power[c] = static_cast<float>(shape.peakWeightAt(altitude_m)[c] / (mie / (rayleigh + mie)));
      break;
    }
  }
  return power;
}

}  // namespace

SkyUniformBlock skyUniformBlock(const Sky& sky) {
  // The shaders hold 4 lanes: a spectral bake goes to them one lane group
  // (sky.laneGroup(g)) at a time, as skybake render --backend gl does.
  if (sky.laneGroupCount() > 1) {
    throw Error(ErrorKind::BadInput,
                fmt::format("the GLSL runtime takes at most 4 channels: this spectral bake has {} (upload each "
                            "Sky::laneGroup(g) of it instead)",
                            sky.channelCount()));
  }
  SkyUniformBlock b{};
  const AtmosphereParameters& a = sky.atmosphere();
  const AtmosphereDomain& d = sky.sampler().domain();
  const TextureSizes& s = sky.contents().sizes;
  const BakeTables& t = sky.tables();
  const MultipleScatteringPhase shape(a, kStoredShapeOrder, sky.contents().multiple_shape_weight);
  const CornetteShanksPhase mie_phase(a.mie_phase_g);
  const CornetteShanksPhase multiple_peak(shape.g());
  const BakedRanges& ranges = sky.bakedRanges();
  const MuSUnitCoordMap unit = MuSUnitCoordMap::of(d);
  const ScatteringMuSCoordMap mu_s_coord = ScatteringMuSCoordMap::of(d, s.scattering_mu_s);

  b.radii_m[0] = static_cast<float>(d.bottom_radius_m);
  b.radii_m[1] = static_cast<float>(d.top_radius_m);
  b.radii_m[2] = static_cast<float>(d.horizonToTopDistance());
  b.sun_disk[0] = static_cast<float>(a.sun_angular_radius_rad);
  const double half_chord = std::sin(0.5 * a.sun_angular_radius_rad);
  b.sun_disk[1] = static_cast<float>(4.0 * half_chord * half_chord);
  b.scattering_domain[0] = static_cast<float>(d.scattering_rho_min_m);
  b.scattering_domain[1] = static_cast<float>(d.scattering_rho_max_m);
  b.scattering_domain[2] = static_cast<float>(mu_s_coord.coord_min);
  b.scattering_domain[3] = static_cast<float>(mu_s_coord.inverse_coord_span);
  b.mu_s_map[0] = static_cast<float>(unit.d_min);
  b.mu_s_map[1] = static_cast<float>(unit.inverse_d_span);
  b.mu_s_map[2] = static_cast<float>(unit.inverse_A);
  b.mu_s_map[3] = static_cast<float>(unit.defined);
  b.mu_s_below[0] = static_cast<float>(unit.below_share);
  b.mu_s_below[1] = static_cast<float>(unit.day_coord_at_horizon);
  b.mu_s_below[2] = static_cast<float>(unit.inverse_mu_s_min);
  b.mu_s_below[3] = static_cast<float>(kSunAxisHorizonSpacing);
  // As Sky's constructor derives its baked sun range.
  b.baked_sun_cosines[0] = static_cast<float>(std::cos(radiansFromDegrees(ranges.sun_zenith_max_deg)));
  b.baked_sun_cosines[1] = static_cast<float>(std::cos(radiansFromDegrees(ranges.sun_zenith_min_deg)));
  b.phase[0] = static_cast<float>(a.mie_phase_g);
  b.phase[1] = static_cast<float>(shape.g());
  b.phase[2] = static_cast<float>(mie_phase.normalisation());
  b.phase[3] = static_cast<float>(multiple_peak.normalisation());
  b.scattering_size[0] = s.scattering_r;
  b.scattering_size[1] = s.scattering_mu;
  b.scattering_size[2] = s.scattering_mu_s;
  b.scattering_size[3] = s.scattering_nu;
  b.table_2d_size[0] = t.optical_depth.width;
  b.table_2d_size[1] = t.optical_depth.height;
  b.table_2d_size[2] = s.irradiance_mu_s;
  b.table_2d_size[3] = s.irradiance_r;
  b.parts[0] = d.scattering_ground_views ? 1 : 0;
  b.parts[1] = sky.hasSingleMie() ? 1 : 0;
  b.parts[2] = t.multiple_density.texels.empty() ? 0 : 1;
  b.parts[3] = t.irradiance.texels.empty() ? 0 : 1;
  b.outputs[0] = sky.outputs().radiance_to_points ? 1 : 0;
  b.outputs[1] = sky.outputs().ground_irradiance ? 1 : 0;
  b.outputs[2] = sky.channelCount();
  b.outputs[3] = sky.channels().kind == ChannelKind::CieXyz ? 1 : 0;
  b.irradiance_rows[0] = d.irradianceCosineRows();
  b.irradiance_rows[1] = d.irradiance_depth_channel;
  b.irradiance_sun[0] = static_cast<float>(d.mu_s_min);
  put(b.sun_irradiance, a.sun_irradiance);
  put(b.solar_radiance, sky.solarRadiance());
  put(b.rayleigh_scattering, a.rayleigh_scattering);
  put(b.mie_scattering, a.mie_scattering);
  put(b.mie_extinction, a.mie_extinction);
  put(b.absorption_extinction, a.absorption_extinction);
  put(b.ground_albedo, a.ground_albedo);
  put(b.column_mie_share_power, columnMieSharePower(sky, shape));
  // A colour bake's channels are X, Y, Z, not wavelengths: its lanes stay 0.
  if (!a.storesCieXyz()) {
    for (int c = 0; c < sky.channelCount(); ++c) b.wavelengths_nm[c] = static_cast<float>(a.wavelengths_nm[c]);
  }
  const NightContinuation& night = sky.sampler().night();
  b.night[0] = static_cast<float>(night.edge_mu_s);
  b.night[1] = static_cast<float>(night.edge_sin);
  b.night[2] = static_cast<float>(night.inverse_tan_half_span);
  b.night[3] = d.scattering_mu_s_coord_min <= 0.0 ? 1.0f : 0.0f;  // as TableSampler::nightScale4D
  put(b.night_exponent, night.exponent);
  put(b.luminance_weights, sky.luminanceWeights());
  const std::vector<WavelengthGroupToXyz>& to_xyz = sky.wavelengthGroupsToXyz();
  if (to_xyz.size() > static_cast<size_t>(kMaxGlIntegralPasses)) {
    throwBadInput(fmt::format("a colour bake of {} wavelength groups: the GLSL library holds at most {}", to_xyz.size(),
                              kMaxGlIntegralPasses));
  }
  const std::int32_t rows = sky.contents().sizes.transmittance_r;
  if (to_xyz.empty()) {
    b.integral_passes[0] = 1;
    for (int c = 0; c < kMaxChannels; ++c) {
      b.pass_rayleigh_weights[c][c] = a.sun_irradiance[c] * a.rayleigh_scattering[c];
      b.pass_mie_weights[c][c] = a.sun_irradiance[c] * a.mie_scattering[c];
    }
  } else {
    // After the X, Y, Z table's rows (SkyGlResources stacks them so).
    b.integral_passes[0] = static_cast<std::int32_t>(to_xyz.size());
    b.integral_passes[1] = rows;
    for (size_t g = 0; g < to_xyz.size(); ++g) {
      for (int c = 0; c < kCieXyzChannels; ++c) {
        put(b.pass_rayleigh_weights[4 * g + c], Spectrum(to_xyz[g].rayleigh[c]));
        put(b.pass_mie_weights[4 * g + c], Spectrum(to_xyz[g].mie[c]));
      }
    }
  }
  b.integral_passes[2] = rows;
  putLayers(b, 0, a.rayleigh_density, "rayleigh");
  putLayers(b, 1, a.mie_density, "mie");
  putLayers(b, 2, a.absorption_density, "absorption");
  return b;
}

std::string skyGlslDefines() {
  std::string out = "// Generated from the C++ constants (runtime/gl/sky_gl_parameters.cpp).\n";
  auto define = [&](const char* name, const std::string& value) { out += fmt::format("#define {} {}\n", name, value); };
  auto floatArray = [](const double(&values)[kGaussNodes]) {
    std::string list;
    for (int i = 0; i < kGaussNodes; ++i) list += (i > 0 ? ", " : "") + glslFloat(values[i]);
    return fmt::format("float[{}]({})", kGaussNodes, list);
  };
  define("SKYBAKE_MAX_DENSITY_LAYERS", std::to_string(kMaxGlDensityLayers));
  define("SKYBAKE_MAX_INTEGRAL_PASSES", std::to_string(kMaxGlIntegralPasses));
  define("SKYBAKE_GAUSS_NODES", std::to_string(kGaussNodes));
  define("SKYBAKE_GAUSS_ABSCISSA", floatArray(kGaussAbscissa));
  define("SKYBAKE_GAUSS_WEIGHT", floatArray(kGaussWeight));
  define("SKYBAKE_MAX_PIECE_OPTICAL_DEPTH", glslFloat(kMaxPieceOpticalDepth));
  define("SKYBAKE_REFINED_OPTICAL_DEPTH", glslFloat(kRefinedOpticalDepth));
  define("SKYBAKE_MAX_PIECES_PER_SUBINTERVAL", std::to_string(kMaxPiecesPerSubinterval));
  define("SKYBAKE_INTEGRATED_SINGLE_SCATTERING_TOP_COSINE", glslFloat(kIntegratedSingleScatteringTopCosine));
  define("SKYBAKE_MAX_IRRADIANCE_DEPTH_FACTOR", glslFloat(kMaxIrradianceDepthFactor));
  define("SKYBAKE_LOOKUP_SINGLE_SCATTERING_SEGMENTS", std::to_string(kLookupSingleScatteringSegments));
  define("SKYBAKE_GROUND_RAY_SUBINTERVALS", std::to_string(kGroundRaySubintervals));
  define("SKYBAKE_MIE_TWILIGHT_FADE_COSINE", glslFloat(kMieTwilightFadeCosine));
  define("SKYBAKE_HORIZON_BLEND_COSINE", glslFloat(kHorizonBlendCosine));
  define("SKYBAKE_DIRECT_SEGMENT_MAX_LENGTH_M", glslFloat(kDirectSegmentMaxLength_m));
  define("SKYBAKE_DIFFERENCE_SEGMENT_MIN_LENGTH_M", glslFloat(kDifferenceSegmentMinLength_m));
  define("SKYBAKE_DIRECT_SEGMENT_SUBINTERVALS", std::to_string(kDirectSegmentSubintervals));
  define("SKYBAKE_GROUND_GRAZE_TOLERANCE_M", glslFloat(kGroundGrazeTolerance_m));
  // Solar eclipses (runtime/physics/eclipse_skylight.h, sky_lookup_constants.h).
  define("SKYBAKE_ECLIPSE_SINGLE_SCATTERING_SEGMENTS", std::to_string(kEclipseSingleScatteringSegments));
  define("SKYBAKE_ECLIPSE_SMALLEST_UNECLIPSED_SINGLE", glslFloat(kEclipseSmallestUneclipsedSingle));
  define("SKYBAKE_ECLIPSE_IRRADIANCE_BANDS", std::to_string(kEclipseIrradianceBands));
  define("SKYBAKE_ECLIPSE_IRRADIANCE_AZIMUTHS", std::to_string(kEclipseIrradianceAzimuths));
  define("SKYBAKE_ECLIPSE_KERNEL_ELEVATIONS", std::to_string(kEclipseKernelElevations));
  define("SKYBAKE_ECLIPSE_KERNEL_AZIMUTHS", std::to_string(kEclipseKernelAzimuths));
  define("SKYBAKE_ECLIPSE_KERNEL_DISTANCES", std::to_string(kEclipseKernelDistances));
  define("SKYBAKE_ECLIPSE_FIRST_DISTANCE_M", glslFloat(kEclipseFirstDistance_m));
  define("SKYBAKE_ECLIPSE_REDIRECTED_SCATTERING_SHARE", glslFloat(kEclipseRedirectedScatteringShare));
  return out;
}

std::string_view skyGlslLibrarySource() { return kGlslLibrarySource; }

std::string skyGlslLibrary() { return skyGlslDefines() + std::string(kGlslLibrarySource); }

bool daylightLookupsSuffice(const Sky& sky, const glm::dvec3& camera_m, const glm::dvec3& sun_dir) {
  const double r = glm::length(camera_m);
  if (!(r > 0.0 && r <= sky.atmosphere().top_radius_m)) return false;
  const double mu_s = glm::dot(camera_m / r, sun_dir);
  // Bakes whose tables hold rays to the ground only: for a scene's bake
  // without them (its ground rays integrated), a test program's received
  // radiance from the daylight program read several times the CPU's on
  // llvmpipe, though each of its parts matched and render's program was
  // right (docs/MEASUREMENTS.md, 2026-12-07): not relied on until understood.
  return sky.sampler().domain().scattering_ground_views && mu_s >= 0.0 &&
         sky.integratedSingleScatteringWeightAt(mu_s) == 0.0;
}

}  // namespace skybake::gl
