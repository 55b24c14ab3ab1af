// A probability density on [0, length] that follows a positive function known
// at equally spaced nodes, exponential between neighbouring nodes. Along a ray
// through an atmosphere, scattering times transmittance is close to
// exponential in distance over a few kilometres, so this proposal tracks it
// within each bin, where a piecewise-constant one (uniform inside a bin)
// mis-weights every sample of a bin the density changes across by orders of
// magnitude: long grazing rays from high altitude, the thin Mie layer.
//
// Sampling takes one uniform number, so quasi-random points stay stratified.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace skybake {

template <int Bins>
class LogLinearProposal {
 public:
  // `node_value[i]` >= 0 at i * length / Bins, i = 0..Bins.
  LogLinearProposal(double length, const std::array<double, Bins + 1>& node_value)
      : bin_length_(length / Bins), node_(node_value) {
    total_ = 0.0;
    for (int i = 0; i < Bins; ++i) {
      mass_[i] = bin_length_ * meanOverBin(i);
      total_ += mass_[i];
    }
  }

  // Whether the function is positive somewhere (else nothing can be sampled).
  bool usable() const { return total_ > 0.0 && std::isfinite(total_); }
  double total() const { return total_; }

  // The point for the uniform number u in [0, 1).
  double sample(double u) const {
    double target = u * total_;
    int bin = 0;
    while (bin + 1 < Bins && target >= mass_[bin]) target -= mass_[bin++];
    const double v = mass_[bin] > 0.0 ? std::clamp(target / mass_[bin], 0.0, 1.0) : 0.5;
    double fraction = v;
    if (exponentialIn(bin)) {
      const double log_ratio = std::log(node_[bin + 1] / node_[bin]);
      fraction = std::log1p(v * std::expm1(log_ratio)) / log_ratio;
    }
    return (bin + std::clamp(fraction, 0.0, 1.0)) * bin_length_;
  }

  // The probability density at t (1/m).
  double pdf(double t) const {
    if (!usable()) return 0.0;
    const int bin = std::clamp(static_cast<int>(t / bin_length_), 0, Bins - 1);
    if (mass_[bin] <= 0.0) return 0.0;
    const double in_bin = exponentialIn(bin) ? valueAt(bin, t / bin_length_ - bin) / meanOverBin(bin) : 1.0;
    return mass_[bin] / total_ * in_bin / bin_length_;
  }

 private:
  // Exponential between the nodes needs both positive and a ratio large
  // enough that log(ratio) is not lost to rounding; otherwise the bin is
  // treated as uniform at the nodes' mean (an exact density all the same).
  bool exponentialIn(int bin) const {
    const double a = node_[bin], b = node_[bin + 1];
    return a > 0.0 && b > 0.0 && std::abs(b / a - 1.0) > kUniformBinRatioTolerance;
  }

  // Mean of the exponential through the two nodes (the logarithmic mean).
  double meanOverBin(int bin) const {
    const double a = node_[bin], b = node_[bin + 1];
    if (!exponentialIn(bin)) return 0.5 * (a + b);
    return (b - a) / std::log(b / a);
  }

  double valueAt(int bin, double fraction) const {
    return node_[bin] * std::pow(node_[bin + 1] / node_[bin], fraction);
  }

  // Below this relative difference of the nodes, log(b/a) loses digits and a
  // uniform bin is as good (the density differs by < 1e-6 across it).
  static constexpr double kUniformBinRatioTolerance = 1e-6;

  double bin_length_;
  std::array<double, Bins + 1> node_;
  std::array<double, Bins> mass_{};
  double total_ = 0.0;
};

}  // namespace skybake
