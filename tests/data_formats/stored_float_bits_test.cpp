// Rounding a float to fewer fraction bits (data_formats/bake_file/stored_float_bits.h):
// the nearest such float, within half its last kept bit, idempotent, and
// every float class kept.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "data_formats/bake_file/stored_float_bits.h"

namespace skybake {
namespace {

// The fraction bits below the `fraction_bits` kept, which must be zero.
uint32_t droppedBits(float value, int fraction_bits) {
  return std::bit_cast<uint32_t>(value) & ((uint32_t{1} << (kFloatFractionBits - fraction_bits)) - 1);
}

TEST(StoredFloatBits, RoundsToNearestWithinHalfTheLastKeptBit) {
  std::mt19937 random(12345);
  // Values over the tables' range (1e-12 to 1e3 W m^-2 nm^-1 and per metre).
  std::uniform_real_distribution<float> log10_value(-12.0f, 3.0f);
  for (int bits : {kMinStoredFractionBits, 12, kDefaultStoredFractionBits, 20, 22}) {
    // Half a unit of the last kept bit, relative to a value of at least 1 in
    // that bit's binade: the bound of rounding to nearest.
    const double bound = std::ldexp(1.0, -(bits + 1));
    for (int i = 0; i < 20000; ++i) {
      const float value = std::pow(10.0f, log10_value(random));
      const float rounded = roundToFractionBits(value, bits);
      EXPECT_LE(std::abs(double(rounded) - value), bound * value) << value << " " << bits;
      EXPECT_EQ(droppedBits(rounded, bits), 0u) << value << " " << bits;
      EXPECT_EQ(roundToFractionBits(rounded, bits), rounded) << value << " " << bits;
      // The nearest: neither neighbour with the same bits kept is closer
      // (one unit of the last kept bit up and down the encoding, which
      // steps across binades correctly).
      const uint32_t unit = uint32_t{1} << (kFloatFractionBits - bits);
      const float above = std::bit_cast<float>(std::bit_cast<uint32_t>(rounded) + unit);
      const float below = std::bit_cast<float>(std::bit_cast<uint32_t>(rounded) - unit);
      EXPECT_LE(std::abs(double(rounded) - value), std::abs(double(above) - value)) << value;
      EXPECT_LE(std::abs(double(rounded) - value), std::abs(double(below) - value)) << value;
      EXPECT_EQ(roundToFractionBits(-value, bits), -rounded);
    }
  }
}

TEST(StoredFloatBits, TiesGoToEvenAndCarriesReachTheNextBinade) {
  const int bits = 16;
  const float unit = std::ldexp(1.0f, -bits);  // the last kept bit of values in [1, 2)
  // 1 + unit/2 lies halfway between 1 (even) and 1 + unit (odd).
  EXPECT_EQ(roundToFractionBits(1.0f + unit / 2, bits), 1.0f);
  // 1 + 3 unit/2 lies halfway between 1 + unit (odd) and 1 + 2 unit (even).
  EXPECT_EQ(roundToFractionBits(1.0f + 3 * unit / 2, bits), 1.0f + 2 * unit);
  // The largest float below 2 rounds up to 2, whose exponent is one more.
  EXPECT_EQ(roundToFractionBits(std::nextafter(2.0f, 0.0f), bits), 2.0f);
}

TEST(StoredFloatBits, EveryBitKeptIsTheIdentityAndSpecialValuesKeepTheirClass) {
  std::mt19937 random(7);
  std::uniform_int_distribution<uint32_t> any_bits;
  for (int i = 0; i < 10000; ++i) {
    const float value = std::bit_cast<float>(any_bits(random));
    if (std::isnan(value)) continue;
    EXPECT_EQ(std::bit_cast<uint32_t>(roundToFractionBits(value, kFloatFractionBits)), std::bit_cast<uint32_t>(value));
  }
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(roundToFractionBits(0.0f, 16), 0.0f);
  EXPECT_TRUE(std::signbit(roundToFractionBits(-0.0f, 16)));
  EXPECT_EQ(roundToFractionBits(inf, 16), inf);
  EXPECT_EQ(roundToFractionBits(-inf, 16), -inf);
  EXPECT_TRUE(std::isnan(roundToFractionBits(std::numeric_limits<float>::quiet_NaN(), 16)));
  // The largest float would round past the largest: it is truncated instead.
  const float largest = std::numeric_limits<float>::max();
  EXPECT_TRUE(std::isfinite(roundToFractionBits(largest, 16)));
  EXPECT_LE(roundToFractionBits(largest, 16), largest);
  // Subnormals stay subnormal or zero, never negative or larger than the
  // smallest normal float.
  const float subnormal = std::numeric_limits<float>::denorm_min() * 12345.0f;
  const float rounded = roundToFractionBits(subnormal, 16);
  EXPECT_GE(rounded, 0.0f);
  EXPECT_LE(rounded, std::numeric_limits<float>::min());
}

}  // namespace
}  // namespace skybake
