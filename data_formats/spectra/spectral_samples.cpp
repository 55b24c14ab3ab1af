#include "data_formats/spectra/spectral_samples.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace skybake {

std::vector<size_t> ascendingOrder(std::span<const double> wavelengths_nm) {
  std::vector<size_t> order(wavelengths_nm.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return wavelengths_nm[a] < wavelengths_nm[b]; });
  return order;
}

LinearWeights linearWeights(std::span<const double> ascending_nm, double wavelength_nm) {
  const size_t last = ascending_nm.size() - 1;
  if (wavelength_nm <= ascending_nm.front()) return {0, 0, 0.0};
  if (wavelength_nm >= ascending_nm[last]) return {last, last, 0.0};
  // The first sample at or above the wavelength; the one before is below it.
  const size_t above = static_cast<size_t>(std::lower_bound(ascending_nm.begin(), ascending_nm.end(), wavelength_nm) -
                                           ascending_nm.begin());
  if (ascending_nm[above] == wavelength_nm) return {above, above, 0.0};
  const double low_nm = ascending_nm[above - 1];
  return {above - 1, above, (wavelength_nm - low_nm) / (ascending_nm[above] - low_nm)};
}

double TabulatedSpectrum::at(double wavelength_nm) const {
  const LinearWeights w = linearWeights(wavelengths_nm, wavelength_nm);
  if (w.low == w.high) return values[w.low];
  return (1.0 - w.weight_high) * values[w.low] + w.weight_high * values[w.high];
}

double TabulatedSpectrum::bandMean(double low_nm, double high_nm) const {
  // The integral of the piecewise-linear spectrum: a trapezoid over each
  // piece of the band between consecutive breakpoints (the band's ends and
  // the samples inside it), which is exact for a straight line.
  double integral = 0.0;
  double from_nm = low_nm;
  double from_value = at(low_nm);
  const auto first_inside = std::upper_bound(wavelengths_nm.begin(), wavelengths_nm.end(), low_nm);
  for (auto it = first_inside; it != wavelengths_nm.end() && *it < high_nm; ++it) {
    const double value = values[static_cast<size_t>(it - wavelengths_nm.begin())];
    integral += 0.5 * (from_value + value) * (*it - from_nm);
    from_nm = *it;
    from_value = value;
  }
  integral += 0.5 * (from_value + at(high_nm)) * (high_nm - from_nm);
  return integral / (high_nm - low_nm);
}

double powerLaw(double reference_nm, double value_at_reference, double exponent, double wavelength_nm) {
  return value_at_reference * std::pow(reference_nm / wavelength_nm, exponent);
}

std::vector<double> evenlySpacedWavelengths(double first_nm, double last_nm, int count) {
  std::vector<double> wavelengths(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    wavelengths[static_cast<size_t>(i)] =
        first_nm + (last_nm - first_nm) * static_cast<double>(i) / static_cast<double>(count - 1);
  }
  // first + (last - first) * 1 can round away from last.
  wavelengths.back() = last_nm;
  return wavelengths;
}

}  // namespace skybake
