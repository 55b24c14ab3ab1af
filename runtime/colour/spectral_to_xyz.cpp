#include "runtime/colour/spectral_to_xyz.h"

#include <fmt/format.h>
#include <cmath>

#include "data_formats/error.h"
#include "data_formats/spectra/spectral_samples.h"
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
  const std::vector<size_t> order = ascendingOrder(wavelengths_nm);
  std::vector<double> ascending_nm(order.size());
  for (size_t k = 0; k < order.size(); ++k) ascending_nm[k] = wavelengths_nm[order[k]];
  for (size_t k = 1; k < order.size(); ++k) {
    if (ascending_nm[k] == ascending_nm[k - 1]) {
      throwBadInput(fmt::format("colour conversion: wavelength {} nm is given twice", ascending_nm[k]));
    }
  }
  auto add = [&](size_t channel, double fraction, const ColourMatchingSample& s) {
    Xyz& w = weights_[channel];
    w.x += fraction * s.xbar * kCie1931Step_nm;
    w.y += fraction * s.ybar * kCie1931Step_nm;
    w.z += fraction * s.zbar * kCie1931Step_nm;
  };
  // Beyond the end samples linearWeights holds the end value, the rule above.
  for (const ColourMatchingSample& s : cie1931Observer()) {
    const LinearWeights w = linearWeights(ascending_nm, s.wavelength_nm);
    add(order[w.low], 1.0 - w.weight_high, s);
    if (w.high != w.low) add(order[w.high], w.weight_high, s);
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
