// Interpolation across a sun axis where the quantity falls roughly
// exponentially with the sun's depression: a cubic through four neighbouring
// texels in the logarithm.
//
// With the sun below the horizon the multiple-scattering density at a point
// falls by 1.5 to 10 times from one sun texel to the next (0.75 to 1.25 deg
// apart at the default sizes). A linear blend of two texels overestimates it
// between them (the density is convex), the more the deeper the sun, and the
// error compounds over the orders: civil twilight read up to 10 % bright
// against the reference. A geometric blend (a line in the logarithm) is
// exact for a pure exponential, but the density's logarithm bends (its decay
// rate changes with depression); against finer tables it read the default
// Earth's astronomical twilight some 3 points darker than this does. A
// Catmull-Rom cubic in the logarithm follows that bend (it is exact where
// the logarithm is quadratic).
#pragma once

#include <algorithm>
#include <cmath>

#include "baker/numerics/vector_exp.h"
#include "data_formats/spectra/spectrum.h"

namespace skybake {

// Catmull-Rom weights at position t in [0, 1] between the second and third
// of four evenly spaced nodes.
struct CubicWeights {
  float before, lower, upper, after;
  static CubicWeights at(float t) {
    const float t2 = t * t, t3 = t2 * t;
    return {0.5f * (-t + 2.0f * t2 - t3), 0.5f * (2.0f - 5.0f * t2 + 3.0f * t3), 0.5f * (t + 4.0f * t2 - 3.0f * t3),
            0.5f * (t3 - t2)};
  }
};

// The interval's two texels (`lower`, `upper`, for the linear blend) and the
// logarithms of four neighbours along the axis: `log_before` and `log_after`
// belong to the texels beyond the interval, or, at an end of the axis, are
// not read: the logarithm is extended linearly there (2 l_lower - l_upper,
// or 2 l_upper - l_lower).
struct LogCubicNeighbours {
  const Spectrum& lower;
  const Spectrum& upper;
  const Spectrum& log_before;
  const Spectrum& log_lower;
  const Spectrum& log_upper;
  const Spectrum& log_after;
  bool before_is_end;
  bool after_is_end;
};

// At position t between `lower` and `upper`. Channels where a logarithm is
// not finite (a zero or negative texel among those the neighbours were
// interpolated from) blend linearly. The cubic is kept within the
// interval's two texels, so data that do not fall monotonically never ring
// beyond them (nor overflow, beside a denormal).
inline Spectrum blendLogCubic(const LogCubicNeighbours& n, float t) {
  const Spectrum linear = n.lower + (n.upper - n.lower) * t;
  const Spectrum log_before = n.before_is_end ? 2.0f * n.log_lower - n.log_upper : n.log_before;
  const Spectrum log_after = n.after_is_end ? 2.0f * n.log_upper - n.log_lower : n.log_after;
  const CubicWeights w = CubicWeights::at(t);
  const Spectrum cubic_log =
      log_before * w.before + n.log_lower * w.lower + n.log_upper * w.upper + log_after * w.after;
  // Channels with a non-finite logarithm compute a value they do not use.
  const Spectrum value =
      expOf(glm::clamp(cubic_log, glm::min(n.log_lower, n.log_upper), glm::max(n.log_lower, n.log_upper)));
  Spectrum out = linear;
  for (int c = 0; c < kMaxChannels; ++c) {
    const bool finite = std::isfinite(log_before[c]) && std::isfinite(n.log_lower[c]) &&
                        std::isfinite(n.log_upper[c]) && std::isfinite(log_after[c]);
    if (finite) out[c] = value[c];
  }
  return out;
}

}  // namespace skybake
