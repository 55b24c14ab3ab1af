// What the scattering-density stage needs that does not change from order to
// order, computed once per bake: per altitude texel, the incident directions'
// zenith nodes, what the directions that end on the ground see of it, and the
// phase functions between every stored view zenith and every incident zenith
// as Fourier series in the azimuth between them.
//
// Why Fourier series: with the sun in the x-z plane of the local frame, the
// incident radiance on a ring of equal zenith angle is an even function of
// azimuth, and a phase function depends on the azimuth difference between
// view and incident direction only. The sum over a ring is then a circular
// convolution: with the ring's radiance as cosine modes A_m (one transform per
// ring and texel row) and the phase function's modes P_m (fixed for the bake),
// the density toward a view of azimuth phi is sum_m cos(m phi) P_m A_m. That
// replaces the phase-weighted sum over all 2048 directions per texel by
// kAzimuthModes terms per zenith node, shared by every nu of a view zenith.
#pragma once

#include <cstdint>
#include <vector>

#include "baker/stages/stage_context.h"

namespace skybake {

// Incident directions: 48 zenith angles x 64 azimuths. On each side of the
// horizon, 16 Gauss-Legendre angles in theta over the sky (or the ground)
// and 8 more within kDensityHorizonBand_rad of the horizon. Bruneton's
// reference implementation uses 16 x 32, which misses the aureole and
// horizon structure of the incident light (docs/MEASUREMENTS.md,
// "Scattering density"); in deep twilight the light reaching a point comes
// from sunlit air seen within a degree or two above its horizon, which 16
// angles spread over the whole sky resolved with one (docs/MEASUREMENTS.md).
inline constexpr int kDensitySideNodes = 16;
inline constexpr int kDensityHorizonBandNodes = 8;
inline constexpr double kDensityHorizonBand_rad = 5.0 * 3.14159265358979323846 / 180.0;
inline constexpr int kDensityZenithNodes = 2 * (kDensitySideNodes + kDensityHorizonBandNodes);
inline constexpr int kDensityAzimuths = 64;

// Cosine modes 0 .. kAzimuthModes - 1 of the azimuth: all the 64 equally
// spaced azimuths resolve (their Nyquist mode, 32, vanishes on midpoint
// azimuths). Rayleigh's phase function has modes 0 to 2 only, so it is exact;
// the Mie peak's modes fall off as g^m (0.8^32 ~ 1e-3 for Earth) and its
// azimuthal mean, which carries all of its energy, is kept exactly.
inline constexpr int kAzimuthModes = kDensityAzimuths / 2;
inline constexpr int kRayleighAzimuthModes = 3;

// One incident zenith node at one altitude.
struct IncidentZenithNode {
  double cos_theta, sin_theta;
  double solid_angle_sr;  // of one of its kDensityAzimuths directions
  bool hits_ground;
  // For directions that hit the ground: transmittance from x to the ground
  // point, and the ground point's up direction in x's frame (horizontal
  // component toward the direction's azimuth, vertical component).
  Spectrum ground_transmittance{0.0f};
  double ground_up_horizontal = 0.0, ground_up_vertical = 0.0;
};

// Everything at one altitude texel.
struct DensityKernelAltitude {
  std::vector<IncidentZenithNode> nodes;  // kDensityZenithNodes, zenith to nadir
  // Azimuthal modes of the phase functions' angular shapes (without their
  // normalisation): [view mu texel][incident node][mode].
  std::vector<float> rayleigh_modes;  // kRayleighAzimuthModes per pair
  std::vector<float> mie_modes;       // kAzimuthModes per pair
};

struct ScatteringDensityKernel {
  std::vector<DensityKernelAltitude> altitudes;  // one per scattering r texel
};

// The kernel's size per (r, mu) texel of the scattering tables: at the default
// sizes 1/8 of a 4D table.
inline constexpr uint64_t kDensityKernelBytesPerRMu =
    kDensityZenithNodes * (kAzimuthModes + kRayleighAzimuthModes) * sizeof(float);

// Built once per bake (about 0.05 s at the default sizes on 2 cores).
ScatteringDensityKernel makeScatteringDensityKernel(const StageContext& ctx, const Texture2D& optical_depth);

}  // namespace skybake
