// Prefiltering the 4D tables across mu_s below the horizon (sun_prefilter.h).
#include "baker/bake/sun_prefilter.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "runtime/tables/table_sampler.h"

namespace skybake {
namespace {

// The share of the geometric blend a lookup makes between two texels
// (skybakeBlendGeometricWhereSteep).
float geometricShare(float a, float b) {
  if (!(a > 0.0f && b > 0.0f)) return 0.0f;
  return kernel_float::skybakeGeometricBlendShare(a > b ? a / b : b / a);
}

// One texel's prefiltered value from its own and its neighbours' along mu_s.
float prefiltered(float below, float value, float above) {
  const float linear_correction = (above - 2.0f * value + below) / 12.0f;
  const float share = 0.5f * (geometricShare(below, value) + geometricShare(value, above));
  float corrected = value - linear_correction;
  if (share > 0.0f && below > 0.0f && value > 0.0f && above > 0.0f) {
    const float log_second_difference = std::log(above) - 2.0f * std::log(value) + std::log(below);
    const float geometric = value * std::exp(-log_second_difference / 12.0f);
    corrected = (1.0f - share) * corrected + share * geometric;
  }
  const float limit = kMaxSunPrefilterShare * std::max(value, 0.0f);
  return value + std::clamp(corrected - value, -limit, limit);
}

}  // namespace

void prefilterAcrossSunBelowHorizon(Texture4D& table, const std::vector<double>& texel_mu_s) {
  // The texels to replace: 1 .. last, every one below the horizon.
  int last = 0;
  while (last + 1 < table.mu_s_size - 1 && texel_mu_s[last + 1] < 0.0) ++last;
  if (last < 1 || table.texels.empty()) return;
  // mu_s is the innermost axis: each (r, mu, nu) holds a contiguous run.
  const size_t runs = table.texels.size() / static_cast<size_t>(table.mu_s_size);
#pragma omp parallel for schedule(static)
  for (size_t run = 0; run < runs; ++run) {
    Spectrum* texels = table.texels.data() + run * table.mu_s_size;
    Spectrum below = texels[0];
    for (int i = 1; i <= last; ++i) {
      const Spectrum value = texels[i];
      for (int c = 0; c < kMaxChannels; ++c) texels[i][c] = prefiltered(below[c], value[c], texels[i + 1][c]);
      below = value;
    }
  }
}

}  // namespace skybake
