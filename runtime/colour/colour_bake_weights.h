// How a colour bake (channels.store = "cie_xyz") turns its wavelengths into
// X, Y, Z: the weights of each wavelength in each channel, and the effective
// per-channel atmosphere the runtime's own integrals use.
//
// Radiance and irradiance tables are linear in the spectrum, so their X, Y, Z
// are sums of each wavelength's table times its colour-matching weight
// (SpectralToXyz: the piecewise-linear spectrum through the wavelengths), the
// one rule every spectral-to-XYZ conversion in skybake uses.
//
// What the runtime computes per channel from the atmosphere's coefficients
// (transmittance between points, the twilight single-scattering integral,
// radiance of short segments, the multiple-scattering shape) cannot be
// summed that way. For those the colour bake states, per channel c,
// sunlight-weighted means over the wavelengths i:
//   p_ci = w_ci E_i / sum_j w_cj E_j    (w: colour-matching weight, E: sun),
//   coefficient_c = sum_i p_ci coefficient_i,
// the mean each channel's sunlight sees, and the optical depth table holds
// the effective optical depth of sunlight
//   tau_c = -ln( sum_i p_ci exp(-tau_i) ),
// exact for the direct sun seen from anywhere and monotone along a ray, so
// transmittance between two points stays in [0, 1]. docs/COLOUR_BAKES.md
// says what each approximation costs.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "data_formats/config/atmosphere_parameters.h"
#include "runtime/colour/spectral_to_xyz.h"

namespace skybake::colour {

class ColourBakeWeights {
 public:
  // The wavelength groups of a colour bake (BakeConfig::colour_groups), in
  // order. Throws Error(BadInput) as SpectralToXyz does.
  explicit ColourBakeWeights(const std::vector<AtmosphereParameters>& groups);

  int wavelengthCount() const { return static_cast<int>(wavelengths_nm_.size()); }
  const std::vector<double>& wavelengths_nm() const { return wavelengths_nm_; }

  // What one unit of wavelength i's spectral quantity adds to channel c
  // (0: X, 1: Y, 2: Z), nm.
  double colourMatching(int c, int i) const { return colour_matching_[c][static_cast<size_t>(i)]; }
  // p_ci above: wavelength i's share of channel c's sunlight; each channel's
  // shares sum to 1.
  double sunlightShare(int c, int i) const { return sunlight_share_[c][static_cast<size_t>(i)]; }

  // tau_c above from every wavelength's optical depth (in wavelength order).
  // Computed relative to the smallest weighted depth, so that no depth too
  // large for exp() in double loses the channel to 0.
  double effectiveOpticalDepth(int c, std::span<const double> optical_depth_per_wavelength) const;

  // The colour bake's atmosphere: `shape` (its geometry, densities and
  // phase g, channel_kind CieXyz) with X, Y, Z quantities: the sun's
  // irradiance integrated (W m^-2), albedo and coefficients as
  // sunlight-weighted means.
  AtmosphereParameters cieXyzAtmosphere(const AtmosphereParameters& shape,
                                        const std::vector<AtmosphereParameters>& groups) const;

 private:
  std::vector<double> wavelengths_nm_;
  std::array<std::vector<double>, kCieXyzChannels> colour_matching_;
  std::array<std::vector<double>, kCieXyzChannels> sunlight_share_;
};

}  // namespace skybake::colour
