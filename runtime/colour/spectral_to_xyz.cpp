#include "runtime/colour/spectral_to_xyz.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "data_formats/error.h"
#include "runtime/colour/cie1931_observer.h"

namespace skybake::colour {

SpectralToXyz::SpectralToXyz(std::span<const double> wavelengths_nm) : weights_(wavelengths_nm.size()) {
  if (wavelengths_nm.empty()) throwBadInput("colour conversion: the spectrum has no samples");
  for (double w : wavelengths_nm) {
    if (!std::isfinite(w) || w <= 0.0) {
      throwBadInput(fmt::format("colour conversion: wavelength {} nm: must be finite and positive", w));
    }
  }
  // The channels in increasing wavelength.
  std::vector<size_t> order(wavelengths_nm.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return wavelengths_nm[a] < wavelengths_nm[b]; });
  for (size_t k = 1; k < order.size(); ++k) {
    if (wavelengths_nm[order[k]] == wavelengths_nm[order[k - 1]]) {
      throwBadInput(fmt::format("colour conversion: wavelength {} nm is given twice", wavelengths_nm[order[k]]));
    }
  }
  auto add = [&](size_t channel, double fraction, const ColourMatchingSample& s) {
    Xyz& w = weights_[channel];
    w.x += fraction * s.xbar * kCie1931Step_nm;
    w.y += fraction * s.ybar * kCie1931Step_nm;
    w.z += fraction * s.zbar * kCie1931Step_nm;
  };
  for (const ColourMatchingSample& s : cie1931Observer()) {
    const double lambda = s.wavelength_nm;
    if (lambda <= wavelengths_nm[order.front()]) {
      add(order.front(), 1.0, s);
    } else if (lambda >= wavelengths_nm[order.back()]) {
      add(order.back(), 1.0, s);
    } else {
      // The first sample above lambda and the one below it.
      size_t above = 1;
      while (wavelengths_nm[order[above]] < lambda) ++above;
      const double low = wavelengths_nm[order[above - 1]];
      const double high = wavelengths_nm[order[above]];
      const double t = (lambda - low) / (high - low);
      add(order[above - 1], 1.0 - t, s);
      add(order[above], t, s);
    }
  }
}

Xyz SpectralToXyz::operator()(std::span<const float> samples) const {
  Xyz xyz;
  for (size_t c = 0; c < weights_.size(); ++c) {
    xyz.x += weights_[c].x * samples[c];
    xyz.y += weights_[c].y * samples[c];
    xyz.z += weights_[c].z * samples[c];
  }
  return xyz;
}

double ybarIntegral_nm() {
  double sum = 0.0;
  for (const ColourMatchingSample& s : cie1931Observer()) sum += s.ybar * kCie1931Step_nm;
  return sum;
}

}  // namespace skybake::colour
