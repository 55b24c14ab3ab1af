// Sky::skyRadianceBatch for a list of view directions, each rounded to float
// as the batch takes them; tests compare it with scalar lookups of the same
// (rounded) directions.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "runtime/sky.h"

namespace skybake::test {

struct BatchLookup {
  glm::dvec3 view;  // the direction as the batch saw it
  RadianceAndTransmittance value;
};

// The views the batch tests look along: zenith 0 to 180 deg in 7.5 deg
// steps (the horizon and both poles among them), azimuth in 45 deg steps;
// `direction(zenith_deg, azimuth_deg)` makes each.
template <typename Direction>
std::vector<glm::dvec3> batchTestViews(Direction direction) {
  std::vector<glm::dvec3> views;
  for (double zenith = 0.0; zenith <= 180.0; zenith += 7.5) {
    for (double azimuth = 0.0; azimuth < 360.0; azimuth += 45.0) views.push_back(direction(zenith, azimuth));
  }
  return views;
}

inline std::vector<BatchLookup> lookUpBatch(const Sky& sky, const glm::dvec3& camera, const glm::dvec3& sun,
                                            const std::vector<glm::dvec3>& views) {
  std::vector<float> x, y, z;
  for (const glm::dvec3& v : views) {
    x.push_back(static_cast<float>(v.x));
    y.push_back(static_cast<float>(v.y));
    z.push_back(static_cast<float>(v.z));
  }
  std::vector<float> radiance[3], transmittance[3];
  SpectrumBatch radiance_out{}, transmittance_out{};
  for (int c = 0; c < 3; ++c) {
    radiance[c].resize(x.size());
    transmittance[c].resize(x.size());
    radiance_out.channel[c] = radiance[c].data();
    transmittance_out.channel[c] = transmittance[c].data();
  }
  sky.skyRadianceBatch(camera, sun, {x.data(), y.data(), z.data(), x.size()}, radiance_out, transmittance_out);
  std::vector<BatchLookup> out;
  for (size_t i = 0; i < x.size(); ++i) {
    BatchLookup l{glm::dvec3(x[i], y[i], z[i]), {Spectrum(0.0f), Spectrum(0.0f)}};
    for (int c = 0; c < 3; ++c) {
      l.value.radiance[c] = radiance[c][i];
      l.value.transmittance[c] = transmittance[c][i];
    }
    out.push_back(l);
  }
  return out;
}

}  // namespace skybake::test
