#include "data_formats/bake_file/table_values.h"

#include <cmath>

#include <fmt/format.h>

#include "data_formats/error.h"

namespace skybake {

void checkTableValues(const std::string& source, const char* part, const std::vector<Spectrum>& texels, int channels) {
  for (size_t i = 0; i < texels.size(); ++i) {
    for (int c = 0; c < channels; ++c) {
      const float v = texels[i][c];
      if (std::isfinite(v) && v >= 0.0f && v <= kMaxTableValue) continue;
      const char* reason = !std::isfinite(v) ? "not a finite number"
                           : v < 0.0f        ? "negative, where the part holds a quantity that is >= 0"
                                             : "larger than any bake writes";
      throwBadInput(fmt::format("{}: part '{}' holds {} at texel {} (channel {}): {}", source, part, v, i, c, reason));
    }
  }
}

}  // namespace skybake
