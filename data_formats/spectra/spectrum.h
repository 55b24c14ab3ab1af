// Per-wavelength quantities. A bake carries 1 to kMaxChannels wavelengths;
// unused lanes are zero. Four lanes map onto one SIMD register, so spectral
// arithmetic costs the same as scalar arithmetic.
#pragma once

#include <algorithm>

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/vec4.hpp>

namespace skybake {

inline constexpr int kMaxChannels = 4;

// float lanes: radiance, irradiance, scattering coefficients in tables.
using Spectrum = glm::vec4;
// double lanes: optical depths and long sums.
using SpectrumD = glm::dvec4;

// The largest lane, e.g. the extinction of the most attenuated channel.
inline double largestChannel(const SpectrumD& s) { return std::max(std::max(s.x, s.y), std::max(s.z, s.w)); }

}  // namespace skybake
