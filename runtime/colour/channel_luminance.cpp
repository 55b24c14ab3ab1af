#include "runtime/colour/channel_luminance.h"

#include "runtime/colour/luminance.h"
#include "runtime/colour/spectral_to_xyz.h"

namespace skybake::colour {

Spectrum luminanceWeights(const AtmosphereParameters& a) {
  Spectrum w(0.0f);
  if (a.storesCieXyz()) {
    w[1] = static_cast<float>(kMaxLuminousEfficacy_lm_per_W);
    return w;
  }
  const std::vector<float> weights = wavelengthLuminanceWeights(a.wavelengths_nm);
  for (int c = 0; c < a.laneCount(); ++c) w[c] = weights[c];
  return w;
}

std::vector<float> wavelengthLuminanceWeights(const std::vector<double>& wavelengths_nm) {
  const SpectralToXyz to_xyz(wavelengths_nm);
  std::vector<float> w(wavelengths_nm.size());
  for (size_t c = 0; c < w.size(); ++c) {
    w[c] = static_cast<float>(luminance_cd_m2(to_xyz.weight(static_cast<int>(c)).y));
  }
  return w;
}

}  // namespace skybake::colour
