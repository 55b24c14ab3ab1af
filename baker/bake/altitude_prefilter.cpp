// Prefiltering the 4D tables across r (altitude_prefilter.h).
#include "baker/bake/altitude_prefilter.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace skybake {

void prefilterAcrossAltitude(Texture4D& table) {
  if (table.r_size < 3 || table.texels.empty()) return;
  // One r row is every (mu, nu, mu_s) texel at that r, contiguous.
  const size_t row = static_cast<size_t>(table.mu_size) * table.nu_size * table.mu_s_size;
  const std::vector<Spectrum> original = table.texels;
#pragma omp parallel for schedule(static)
  for (int r = 1; r < table.r_size - 1; ++r) {
    const Spectrum* below = original.data() + static_cast<size_t>(r - 1) * row;
    const Spectrum* at = original.data() + static_cast<size_t>(r) * row;
    const Spectrum* above = original.data() + static_cast<size_t>(r + 1) * row;
    Spectrum* out = table.texels.data() + static_cast<size_t>(r) * row;
    for (size_t i = 0; i < row; ++i) {
      for (int c = 0; c < kMaxChannels; ++c) {
        const float value = at[i][c];
        const float limit = kMaxAltitudePrefilterShare * std::max(value, 0.0f);
        const float correction = (above[i][c] - 2.0f * value + below[i][c]) / 12.0f;
        out[i][c] = value - std::clamp(correction, -limit, limit);
      }
    }
  }
}

}  // namespace skybake
