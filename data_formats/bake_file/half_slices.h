// A 4D table stored as half floats (bake.precision = "half", FORMAT.md
// "Half storage"): each (r, mu_s) slice is scaled by its own power of two
// before it is rounded to half, so that every slice uses half's whole range.
//
// Half's normal range is 6.1e-5 to 65504, with 11 significant bits. The
// tables span far more: a day sky's radiance over the phase is near 1, the
// multiple-scattering density near 1e-6 per metre, and both fall by many
// orders of magnitude as the sun sinks through twilight. Unscaled, the
// twilight values would be half subnormals (a few significant bits) or 0.
// Within one (r, mu_s) slice, though, the sun's depression is fixed and the
// values span the view directions only, a few orders of magnitude. Scaling
// each slice so that its largest value lies in [2^14, 2^15) keeps every value
// down to 2^-29 (2e-9) of that largest one a normal half, within 2^-11
// (4.9e-4) of itself. A power of two scales exactly, so the rounding to half
// is the only change, and a reader restores each value as half * 2^exponent.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "data_formats/bake_file/textures.h"
#include "data_formats/spectra/spectrum.h"

namespace skybake {

// The exponent of the power of two that brings a slice's largest value into
// [2^kHalfSliceLargestExponent, 2^(kHalfSliceLargestExponent + 1)): one
// binade below half's largest (65504), so no rounding can overflow it.
inline constexpr int kHalfSliceLargestExponent = 14;
// The exponents a file may state. The tables' values lie in [0, 1e36]
// (table_values.h, 2^120) and down to float's smallest subnormal (2^-149),
// so a slice's exponent lies in [-149 - 14, 120 - 14]; a reader refuses
// others, which no writer makes.
inline constexpr int kMinHalfSliceExponent = -163;
inline constexpr int kMaxHalfSliceExponent = 106;

// The 4D tables' atlas layout (textures.h): texel (r, mu, mu_s, nu) lies in
// slice r * mu_s_size + mu_s.
struct HalfSliceLayout {
  int r_size = 0;
  int mu_size = 0;
  int mu_s_size = 0;
  int nu_size = 0;
  static HalfSliceLayout of(const Texture4D& t) { return {t.r_size, t.mu_size, t.mu_s_size, t.nu_size}; }
  size_t sliceCount() const { return static_cast<size_t>(r_size) * mu_s_size; }
  // Calls fn(texel index, slice index) for every texel, in memory order.
  template <typename Fn>
  void forEachTexel(Fn&& fn) const {
    size_t texel = 0;
    for (int r = 0; r < r_size; ++r) {
      const size_t first_slice = static_cast<size_t>(r) * mu_s_size;
      for (int row = 0; row < mu_size * nu_size; ++row) {
        for (int mu_s = 0; mu_s < mu_s_size; ++mu_s) fn(texel++, first_slice + mu_s);
      }
    }
  }
};

// value * 2^exponent, exactly as std::ldexp gives it, by one multiplication
// where 2^exponent is a normal float (ldexp's integer work was a tenth of a
// bake's write).
inline float scaledByPowerOfTwo(float value, int exponent) {
  if (exponent < -126 || exponent > 127) return std::ldexp(value, exponent);
  return value * std::bit_cast<float>(static_cast<uint32_t>(exponent + 127) << 23);
}

// The lanes of one table that share a part's exponents: the first
// `channels` lanes of `texels`.
struct HalfSliceLanes {
  const std::vector<Spectrum>* texels;
  int channels;
};

// Each slice's exponent for texels laid out as `layout`, the largest value
// taken over every one of `lanes` (a table and the combined single Mie
// channel stored beside it share their exponents). A
// slice of zeros gets 0. The exponents are those of the values as stored:
// where rounding the largest value to half carries it into the next binade,
// the slice takes the next exponent, so that the exponents of stored values
// are the ones they were stored with.
std::vector<int> halfSliceExponents(const HalfSliceLayout& layout, const std::vector<HalfSliceLanes>& lanes);

// `value` as the file stores it in a slice of exponent `exponent`: scaled,
// rounded to the nearest half, scaled back. Exact for values stored before.
float roundToScaledHalf(float value, int exponent);

// Rounds the first `channels` lanes of `texels` as a half file stores them
// with `exponents` (halfSliceExponents), so that a bake in memory and its
// file read back agree to the bit.
void roundToScaledHalf(const HalfSliceLayout& layout, const std::vector<int>& exponents, std::vector<Spectrum>& texels,
                       int channels);

}  // namespace skybake
