// The sRGB transfer function (IEC 61966-2-1:1999): linear light in [0, 1]
// to the encoded value in [0, 1] and back.
#pragma once

#include <algorithm>
#include <cmath>

namespace skybake::colour {

// Where the standard's linear segment near black meets its power curve.
inline constexpr double kSrgbLinearSegmentEnd = 0.0031308;       // linear light
inline constexpr double kSrgbEncodedLinearSegmentEnd = 0.04045;  // encoded value

// Linear light, clamped to [0, 1] (a display shows nothing outside it).
inline double srgbEncode(double linear) {
  const double v = std::clamp(linear, 0.0, 1.0);
  return v <= kSrgbLinearSegmentEnd ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

inline double srgbDecode(double encoded) {
  const double v = std::clamp(encoded, 0.0, 1.0);
  return v <= kSrgbEncodedLinearSegmentEnd ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

}  // namespace skybake::colour
