// Prefiltering the 4D tables across r (altitude_prefilter.h).
#include "baker/bake/altitude_prefilter.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace skybake {

void prefilterAcrossAltitude(Texture4D& table) {
  if (table.r_size < 3 || table.texels.empty()) return;
  // One r row is every (mu, nu, mu_s) texel at that r, contiguous. Rows are
  // replaced in order, each from its own and its neighbours' values as
  // they were: the row below is kept aside before it is replaced (two rows
  // of memory rather than a copy of the table, which is tens of MiB).
  const size_t row = static_cast<size_t>(table.mu_size) * table.nu_size * table.mu_s_size;
  std::vector<Spectrum> below(table.texels.begin(), table.texels.begin() + static_cast<std::ptrdiff_t>(row));
  std::vector<Spectrum> at(row);
  for (int r = 1; r < table.r_size - 1; ++r) {
    Spectrum* out = table.texels.data() + static_cast<size_t>(r) * row;
    const Spectrum* above = out + row;
    std::copy(out, out + row, at.begin());
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < row; ++i) {
      for (int c = 0; c < kMaxChannels; ++c) {
        const float value = at[i][c];
        const float limit = kMaxAltitudePrefilterShare * std::max(value, 0.0f);
        const float correction = (above[i][c] - 2.0f * value + below[i][c]) / 12.0f;
        out[i][c] = value - std::clamp(correction, -limit, limit);
      }
    }
    std::swap(below, at);
  }
}

}  // namespace skybake
