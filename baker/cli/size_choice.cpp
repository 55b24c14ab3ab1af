#include "baker/cli/size_choice.h"

#include <algorithm>
#include <cmath>

namespace skybake {
namespace {

int scaledSize(int size, double scale, int minimum = 2, bool even = false) {
  int s = std::max(minimum, static_cast<int>(std::lround(size * scale)));
  if (even && s % 2 != 0) ++s;
  return s;
}

}  // namespace

const std::vector<SweepPoint>& earthSweep() {
  // docs/ERROR_VS_TIME.md, "The default sweep" (2 cores, sun axis to 108 deg
  // on 36 texels). Twilight is left out: from 0.75x on it is within 1 point
  // of the reference's own noise there (3.3, 2.9 and 2.7 % against 2.4 %), so
  // it says little about the sizes.
  static const std::vector<SweepPoint> points = {
      {0.5, 2.37, 1.85, 0.59},
      {0.75, 0.82, 0.94, 1.9},
      {1.0, 0.39, 0.44, 5.6},
      {1.5, 0.23, 0.35, 24.2},
  };
  return points;
}

double worstPercent(const SweepPoint& p) { return std::max(p.day_percent, p.low_sun_percent); }

std::optional<SizeChoice> chooseSizesForError(double target_percent) {
  for (const SweepPoint& p : earthSweep()) {
    if (worstPercent(p) <= target_percent) {
      SizeChoice c;
      c.scale = p.scale;
      c.predicted_percent = worstPercent(p);
      c.predicted_bake_seconds = p.bake_seconds;
      c.sizes = scaledDefaultSizes(p.scale);
      return c;
    }
  }
  return std::nullopt;
}

TextureSizes scaledDefaultSizes(double scale) {
  const TextureSizes d;
  TextureSizes s;
  s.transmittance_mu = scaledSize(d.transmittance_mu, scale);
  s.transmittance_r = scaledSize(d.transmittance_r, scale);
  s.irradiance_mu_s = scaledSize(d.irradiance_mu_s, scale);
  s.irradiance_r = scaledSize(d.irradiance_r, scale);
  s.scattering_r = scaledSize(d.scattering_r, scale);
  s.scattering_mu = scaledSize(d.scattering_mu, scale, 4, true);
  s.scattering_mu_s = scaledSize(d.scattering_mu_s, scale);
  s.scattering_nu = scaledSize(d.scattering_nu, scale);
  return s;
}

}  // namespace skybake
