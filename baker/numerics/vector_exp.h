// exp and log of spectra's channels in vector instruction sequences.
//
// glibc's vector math library (libmvec) has 4- and 8-wide expf, and GCC calls
// them from loops marked `omp simd` when expf is declared with the `simd`
// attribute. glibc's headers declare it so only under -ffast-math, which
// skybake does not use (it changes NaN and infinity handling), so it is
// declared here, and logf with it. libmvec's expf and logf are within 4 ulp of
// the scalar ones; the bake's tables are stored as float, whose rounding is
// 1 ulp.
#pragma once

#include <cmath>
#include <cstddef>

#include "data_formats/spectra/spectrum.h"

extern "C" __attribute__((simd("notinbranch"))) float expf(float) noexcept;
extern "C" __attribute__((simd("notinbranch"))) float logf(float) noexcept;

namespace skybake {

static_assert(kMaxChannels == 4, "a Spectrum is built from 4 channels below");

// exp(x) per channel.
inline Spectrum expOf(const Spectrum& x) {
  alignas(16) float in[kMaxChannels], out[kMaxChannels];
  for (int c = 0; c < kMaxChannels; ++c) in[c] = x[c];
#pragma omp simd
  for (int c = 0; c < kMaxChannels; ++c) out[c] = expf(in[c]);
  return Spectrum(out[0], out[1], out[2], out[3]);
}

// exp(-x) per channel.
inline Spectrum expOfNegated(const Spectrum& x) { return expOf(-x); }

// log per channel of `count` spectra into `out`: -inf for a zero channel,
// NaN for a negative one (callers test the values before they use these).
inline void logOfSpectra(const Spectrum* in, Spectrum* out, size_t count) {
  static_assert(sizeof(Spectrum) == kMaxChannels * sizeof(float), "a Spectrum is its channels, packed");
  const float* x = &in[0][0];
  float* y = &out[0][0];
  const size_t n = count * kMaxChannels;
#pragma omp simd
  for (size_t k = 0; k < n; ++k) y[k] = logf(x[k]);
}

}  // namespace skybake
