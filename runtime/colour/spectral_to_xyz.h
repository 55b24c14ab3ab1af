// CIE XYZ tristimulus values of a spectrum known at a few wavelengths (a
// bake's channels).
//
// The rule: the spectrum between its samples is the straight line through
// its two neighbours (samples sorted by wavelength: a bake's channels need
// not be), and beyond the shortest and the longest sample it keeps that
// sample's value. That spectrum is integrated against the CIE 1931
// colour-matching functions by the rule CIE 015 gives for tabulated data:
// the sum over the table's wavelengths (360 to 830 nm every 5 nm) of the
// spectrum times each function times 5 nm.
//
// What it means for a three-sample bake (680, 550, 440 nm): a flat
// spectrum, and any spectrum that is linear in wavelength between 440 and
// 680 nm and flat outside, is integrated exactly; the sky's smooth spectra
// (Rayleigh's lambda^-4 times the sun's) lie close to such a line between
// neighbouring samples. Holding the end values is what keeps a flat spectrum
// white; falling to zero outside the samples would drop the blue half of
// zbar below 440 nm and turn every colour yellow. A one-channel bake is
// flat everywhere, so it comes out achromatic (equal-energy white).
#pragma once

#include <array>
#include <span>
#include <vector>

namespace skybake::colour {

struct Xyz {
  double x = 0.0, y = 0.0, z = 0.0;
};

class SpectralToXyz {
 public:
  // The sample wavelengths in the order the samples will come in. Throws
  // Error(BadInput) for none, for a wavelength that is not finite and
  // positive, and for a wavelength given twice.
  explicit SpectralToXyz(std::span<const double> wavelengths_nm);

  // The integrals of the spectrum times xbar, ybar and zbar over
  // wavelength: samples in a unit per nm (W m^-2 sr^-1 nm^-1 for spectral
  // radiance) give X, Y, Z in that unit times nm (W m^-2 sr^-1). `samples`
  // holds one value per wavelength, in the constructor's order.
  Xyz operator()(std::span<const float> samples) const;

  // What one unit of sample `channel` adds to X, Y and Z (nm): the rule is
  // linear in the samples.
  const Xyz& weight(int channel) const { return weights_[static_cast<size_t>(channel)]; }
  int channelCount() const { return static_cast<int>(weights_.size()); }

 private:
  std::vector<Xyz> weights_;
};

// The integral of ybar over wavelength, 106.857 nm: Y of a flat spectrum of
// one unit per nm.
double ybarIntegral_nm();

}  // namespace skybake::colour
