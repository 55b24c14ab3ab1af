// How many of float's 23 fraction bits a bake file keeps (bake.
// stored_fraction_bits, FORMAT.md "Stored precision"). The tables are
// computed in double and float; what they hold below about 1e-5 of a value
// is rounding noise of the computation, not information: the tables'
// interpolation error is 1e-3 and more. ZIP cannot compress noise, so those
// bits are rounded away before the file is written: 16 bits keep every
// value within 2^-17 = 7.6e-6 of itself and make the built-in Earth's file
// 8.5 % smaller (docs/FILE_SIZE.md).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace skybake {

// Float's fraction bits: a file that keeps them all stores every value
// exactly (files written without the attribute).
inline constexpr int kFloatFractionBits = 23;
// The default: relative rounding at most 2^-17 = 7.6e-6, 130 times below
// the tables' smallest interpolation error (1e-3), so no lookup and no
// validate figure moves by more than that.
inline constexpr int kDefaultStoredFractionBits = 16;
// Half's precision: fewer bits would be coarser than bake.precision =
// "half", which is the way to ask for that.
inline constexpr int kMinStoredFractionBits = 10;

// `value` rounded to the nearest float with `fraction_bits` fraction bits
// (ties to even), so its relative change is at most 2^-(fraction_bits + 1).
// Zeros, subnormals, infinities and NaNs keep their class; a value that
// would round up past the largest float is truncated instead.
inline float roundToFractionBits(float value, int fraction_bits) {
  const int dropped = kFloatFractionBits - fraction_bits;
  if (dropped <= 0 || !std::isfinite(value)) return value;
  const uint32_t bits = std::bit_cast<uint32_t>(value);
  const uint32_t dropped_mask = (uint32_t{1} << dropped) - 1;
  const uint32_t kept_lowest_bit = (bits >> dropped) & 1u;
  // Adding half an ulp of the kept bits, less one unless the kept part is
  // odd, rounds to nearest with ties to even; a carry runs into the
  // exponent, which is the next binade's correct value.
  const uint32_t rounded = (bits + (dropped_mask >> 1) + kept_lowest_bit) & ~dropped_mask;
  const float out = std::bit_cast<float>(rounded);
  return std::isfinite(out) ? out : std::bit_cast<float>(bits & ~dropped_mask);
}

}  // namespace skybake
