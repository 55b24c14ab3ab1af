// A bake's lane groups: a spectral bake's groups are ordinary Skies
// (sky.h), whose lookups Sky::everyChannel joins into one value per channel.
#include <string>

#include "data_formats/error.h"
#include "runtime/sky.h"

namespace skybake {

const Sky& Sky::laneGroup(int g) const {
  if (g < 0 || g >= laneGroupCount()) {
    throw Error(ErrorKind::BadInput, "laneGroup(" + std::to_string(g) + "): the bake has " +
                                         std::to_string(laneGroupCount()) + " lane groups");
  }
  return lane_groups_.empty() ? *this : *lane_groups_[static_cast<size_t>(g)];
}

void Sky::refuseSpectrumLookup(const char* lookup) const {
  throw Error(ErrorKind::BadInput,
              std::string(lookup) + ": a spectral bake of " + std::to_string(channelCount()) +
                  " wavelengths returns them through everyChannel or per lane group of 4 (laneGroup(g)); a Spectrum "
                  "holds 4");
}

double Sky::luminance(std::span<const float> channel_values) const {
  if (channel_values.size() != channel_luminance_weights_.size()) {
    throw Error(ErrorKind::BadInput, "luminance: " + std::to_string(channel_values.size()) + " values for a bake of " +
                                         std::to_string(channel_luminance_weights_.size()) + " channels");
  }
  double sum = 0.0;
  for (size_t c = 0; c < channel_values.size(); ++c) {
    sum += static_cast<double>(channel_luminance_weights_[c]) * channel_values[c];
  }
  return sum;
}

}  // namespace skybake
