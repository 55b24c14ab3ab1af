// The sRGB transfer function (IEC 61966-2-1:1999): linear light in [0, 1]
// to the encoded value in [0, 1] and back, and the display encoding of
// skybake's previews (the kernel runtime/kernel/display_encoding.glsl in
// double, the one source the shaders share).
#pragma once

#include <algorithm>
#include <cmath>

#include "data_formats/kernel/kernel_language.h"

namespace skybake {
namespace kernel {
#include "runtime/kernel/display_encoding.glsl"
}  // namespace kernel

namespace colour {

// Where the standard's linear segment near black meets its power curve.
inline constexpr double kSrgbLinearSegmentEnd = SKYBAKE_SRGB_LINEAR_SEGMENT_END;  // linear light
inline constexpr double kSrgbEncodedLinearSegmentEnd = 0.04045;                   // encoded value

// Linear light, clamped to [0, 1] (a display shows nothing outside it).
inline double srgbEncode(double linear) { return kernel::skybakeSrgbEncode(linear); }

inline double srgbDecode(double encoded) {
  const double v = std::clamp(encoded, 0.0, 1.0);
  return v <= kSrgbEncodedLinearSegmentEnd ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

}  // namespace colour
}  // namespace skybake
