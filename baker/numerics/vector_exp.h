// exp of the channels of a spectrum in one vector instruction sequence.
//
// glibc's vector math library (libmvec) has 4- and 8-wide expf, and GCC calls
// them from loops marked `omp simd` when expf is declared with the `simd`
// attribute. glibc's headers declare it so only under -ffast-math, which
// skybake does not use (it changes NaN and infinity handling), so it is
// declared here. libmvec's expf is within 4 ulp of the scalar one; the bake's
// transmittances are stored as float, whose rounding is 1 ulp.
#pragma once

#include <cmath>

#include "data_formats/spectrum.h"

extern "C" __attribute__((simd("notinbranch"))) float expf(float) noexcept;

namespace skybake {

static_assert(kMaxChannels == 4, "a Spectrum is built from 4 channels below");

// exp(-x) per channel.
inline Spectrum expOfNegated(const Spectrum& x) {
  alignas(16) float in[kMaxChannels], out[kMaxChannels];
  for (int c = 0; c < kMaxChannels; ++c) in[c] = -x[c];
#pragma omp simd
  for (int c = 0; c < kMaxChannels; ++c) out[c] = expf(in[c]);
  return Spectrum(out[0], out[1], out[2], out[3]);
}

}  // namespace skybake
