// A spectrum known at sample wavelengths, and the rules that read it at other
// wavelengths: the one place that sorts samples by wavelength and
// interpolates between them, shared by the config (spectra resampled to a
// bake's wavelengths) and the colour module (a bake's channels to CIE XYZ).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace skybake {

// The indices of `wavelengths_nm` in increasing wavelength (a stable sort, so
// equal wavelengths keep their order; callers that need distinct ones check).
std::vector<size_t> ascendingOrder(std::span<const double> wavelengths_nm);

// How a wavelength is read from samples at increasing wavelengths: the
// straight line between the sample below it and the sample above it,
// value = (1 - weight_high) * sample[low] + weight_high * sample[high].
// At a sample's own wavelength low == high and weight_high == 0, so the
// sample is returned exactly. Below the first sample and above the last the
// end sample is held (low == high == the end); callers that must not
// extrapolate check the range first.
struct LinearWeights {
  size_t low = 0;
  size_t high = 0;
  double weight_high = 0.0;
};
LinearWeights linearWeights(std::span<const double> ascending_nm, double wavelength_nm);

// A tabulated spectrum: strictly increasing wavelengths (nm), one value each.
struct TabulatedSpectrum {
  std::vector<double> wavelengths_nm;
  std::vector<double> values;

  double firstWavelength_nm() const { return wavelengths_nm.front(); }
  double lastWavelength_nm() const { return wavelengths_nm.back(); }
  // Whether [low_nm, high_nm] lies inside the tabulated range.
  bool covers(double low_nm, double high_nm) const {
    return low_nm >= firstWavelength_nm() && high_nm <= lastWavelength_nm();
  }
  // The piecewise-linear spectrum at `wavelength_nm` (linearWeights).
  double at(double wavelength_nm) const;
  // The mean of the piecewise-linear spectrum over [low_nm, high_nm]
  // (low < high, inside the range): its exact integral over the band
  // divided by the band's width.
  double bandMean(double low_nm, double high_nm) const;
};

// A power law in wavelength: value_at_reference * (reference_nm /
// wavelength_nm)^exponent. Rayleigh scattering is exponent 4; aerosol
// (Mie) scattering and extinction follow it with the Angstrom exponent.
double powerLaw(double reference_nm, double value_at_reference, double exponent, double wavelength_nm);

// `count` (>= 2) wavelengths evenly spaced from first_nm to last_nm, both
// ends included exactly.
std::vector<double> evenlySpacedWavelengths(double first_nm, double last_nm, int count);

}  // namespace skybake
