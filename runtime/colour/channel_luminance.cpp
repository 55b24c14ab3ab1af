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
  const SpectralToXyz to_xyz(a.wavelengths_nm);
  for (int c = 0; c < a.channelCount(); ++c) w[c] = static_cast<float>(luminance_cd_m2(to_xyz.weight(c).y));
  return w;
}

}  // namespace skybake::colour
