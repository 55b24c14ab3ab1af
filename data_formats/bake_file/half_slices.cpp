// Half storage of the 4D tables, one power of two per (r, mu_s) slice (half_slices.h).
#include "data_formats/bake_file/half_slices.h"

#include <algorithm>
#include <cmath>

#include <Imath/half.h>

namespace skybake {
namespace {

// The exponent that brings `largest` (> 0, finite) into half's top binade
// but one.
int exponentOfLargest(float largest) { return std::ilogb(largest) - kHalfSliceLargestExponent; }

}  // namespace

float roundToScaledHalf(float value, int exponent) {
  const Imath::half stored(scaledByPowerOfTwo(value, -exponent));
  return scaledByPowerOfTwo(static_cast<float>(stored), exponent);
}

std::vector<int> halfSliceExponents(const HalfSliceLayout& layout, const std::vector<HalfSliceLanes>& lanes) {
  std::vector<float> largest(layout.sliceCount(), 0.0f);
  for (const HalfSliceLanes& l : lanes) {
    if (l.texels->empty()) continue;  // a table a lane group lacks: zeros
    layout.forEachTexel([&](size_t t, size_t slice) {
      float& slice_largest = largest[slice];
      for (int c = 0; c < l.channels; ++c) slice_largest = std::max(slice_largest, std::abs((*l.texels)[t][c]));
    });
  }
  std::vector<int> exponents(largest.size(), 0);
  for (size_t s = 0; s < largest.size(); ++s) {
    if (!(largest[s] > 0.0f) || !std::isfinite(largest[s])) continue;
    const int exponent = exponentOfLargest(largest[s]);
    // Rounding is monotonic: the largest value stored is the largest value rounded.
    exponents[s] = exponentOfLargest(roundToScaledHalf(largest[s], exponent));
  }
  return exponents;
}

void roundToScaledHalf(const HalfSliceLayout& layout, const std::vector<int>& exponents, std::vector<Spectrum>& texels,
                       int channels) {
  if (texels.empty()) return;
  layout.forEachTexel([&](size_t t, size_t slice) {
    for (int c = 0; c < channels; ++c) texels[t][c] = roundToScaledHalf(texels[t][c], exponents[slice]);
  });
}

}  // namespace skybake
