// Every channel of a bake through its lane groups: a spectral bake's groups
// are ordinary Skies (sky.h), whose Spectrum lookups are joined here into
// one value per channel.
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
                  " wavelengths returns them from the channel lookups (channelSkyRadiance, ...) or per lane group "
                  "of 4 (laneGroup(g)); a Spectrum holds 4");
}

template <typename Lookup>
std::vector<float> Sky::joinedChannels(Lookup&& lookup) const {
  std::vector<float> out;
  out.reserve(static_cast<size_t>(channelCount()));
  for (int g = 0; g < laneGroupCount(); ++g) {
    const Sky& group = laneGroup(g);
    const Spectrum lanes = lookup(group);
    for (int c = 0; c < group.channelCount(); ++c) out.push_back(lanes[c]);
  }
  return out;
}

namespace {

// The radiance and transmittance lanes of every group, from one lookup per group.
template <typename Lookup>
ChannelRadianceAndTransmittance joinedRadiance(const Sky& sky, Lookup&& lookup) {
  ChannelRadianceAndTransmittance out;
  for (int g = 0; g < sky.laneGroupCount(); ++g) {
    const Sky& group = sky.laneGroup(g);
    const RadianceAndTransmittance v = lookup(group);
    for (int c = 0; c < group.channelCount(); ++c) {
      out.radiance.push_back(v.radiance[c]);
      out.transmittance.push_back(v.transmittance[c]);
    }
  }
  return out;
}

}  // namespace

ChannelRadianceAndTransmittance Sky::channelSkyRadiance(const glm::dvec3& camera, const glm::dvec3& view_dir,
                                                        const glm::dvec3& sun_dir, double shadow_length_m) const {
  return joinedRadiance(
      *this, [&](const Sky& group) { return group.skyRadiance(camera, view_dir, sun_dir, shadow_length_m); });
}

ChannelRadianceAndTransmittance Sky::channelReceivedRadiance(const glm::dvec3& camera, const glm::dvec3& view_dir,
                                                             const glm::dvec3& sun_dir) const {
  return joinedRadiance(*this, [&](const Sky& group) { return group.receivedRadiance(camera, view_dir, sun_dir); });
}

ChannelRadianceAndTransmittance Sky::channelRadianceToPoint(const glm::dvec3& camera, const glm::dvec3& point,
                                                            const glm::dvec3& sun_dir, double shadow_length_m) const {
  return joinedRadiance(
      *this, [&](const Sky& group) { return group.radianceToPoint(camera, point, sun_dir, shadow_length_m); });
}

ChannelSunAndSkyIrradiance Sky::channelIrradiance(const glm::dvec3& point, const glm::dvec3& normal,
                                                  const glm::dvec3& sun_dir) const {
  ChannelSunAndSkyIrradiance out;
  for (int g = 0; g < laneGroupCount(); ++g) {
    const Sky& group = laneGroup(g);
    const SunAndSkyIrradiance v = group.irradiance(point, normal, sun_dir);
    for (int c = 0; c < group.channelCount(); ++c) {
      out.sun.push_back(v.sun[c]);
      out.sky.push_back(v.sky[c]);
    }
  }
  return out;
}

std::vector<float> Sky::channelTransmittance(const glm::dvec3& a, const glm::dvec3& b) const {
  return joinedChannels([&](const Sky& group) { return group.transmittance(a, b); });
}

std::vector<float> Sky::channelSolarRadiance() const {
  return joinedChannels([](const Sky& group) { return group.solarRadiance(); });
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
