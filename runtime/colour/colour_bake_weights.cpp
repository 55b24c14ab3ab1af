#include "runtime/colour/colour_bake_weights.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "data_formats/error.h"

namespace skybake::colour {

ColourBakeWeights::ColourBakeWeights(const std::vector<AtmosphereParameters>& groups) {
  for (const AtmosphereParameters& g : groups) {
    if (g.storesCieXyz()) throw Error(ErrorKind::Internal, "ColourBakeWeights: a wavelength group holds XYZ");
    wavelengths_nm_.insert(wavelengths_nm_.end(), g.wavelengths_nm.begin(), g.wavelengths_nm.end());
  }
  const SpectralToXyz to_xyz(wavelengths_nm_);
  const std::vector<double> sun = groupLaneValues(groups, &AtmosphereParameters::sun_irradiance);
  const size_t n = wavelengths_nm_.size();
  for (int c = 0; c < kCieXyzChannels; ++c) {
    colour_matching_[c].resize(n);
    sunlight_share_[c].resize(n);
    double sunlight = 0.0, matching = 0.0;
    for (size_t i = 0; i < n; ++i) {
      const Xyz& w = to_xyz.weight(static_cast<int>(i));
      colour_matching_[c][i] = c == 0 ? w.x : c == 1 ? w.y : w.z;
      sunlight += colour_matching_[c][i] * sun[i];
      matching += colour_matching_[c][i];
    }
    // A dark sun (all zero) weights the wavelengths by the colour-matching
    // functions alone: the coefficients still have to be means of the
    // wavelengths' (every channel's matching weights are positive: the
    // functions are positive over the visible range and the end values are
    // held beyond the samples).
    for (size_t i = 0; i < n; ++i) {
      sunlight_share_[c][i] =
          sunlight > 0.0 ? colour_matching_[c][i] * sun[i] / sunlight : colour_matching_[c][i] / matching;
    }
  }
}

double ColourBakeWeights::effectiveOpticalDepth(int c, std::span<const double> tau) const {
  const std::vector<double>& p = sunlight_share_[c];
  double smallest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < p.size(); ++i) {
    if (p[i] > 0.0) smallest = std::min(smallest, tau[i]);
  }
  if (!std::isfinite(smallest)) return 0.0;  // no wavelength weighs in: nothing to attenuate
  // sum p_i exp(-(tau_i - smallest)) >= p of the smallest > 0: no log of 0.
  double sum = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    if (p[i] > 0.0) sum += p[i] * std::exp(-(tau[i] - smallest));
  }
  // sum <= sum p_i = 1, so tau_c >= the smallest depth; the shares' rounding
  // can put sum a few ulps above 1, which would make a zero depth negative
  // (a table value the file refuses).
  return std::max(smallest, smallest - std::log(sum));
}

AtmosphereParameters ColourBakeWeights::cieXyzAtmosphere(const AtmosphereParameters& shape,
                                                         const std::vector<AtmosphereParameters>& groups) const {
  AtmosphereParameters a = shape;
  a.channel_kind = ChannelKind::CieXyz;
  a.wavelengths_nm = wavelengths_nm_;
  auto sunlightMean = [&](Spectrum AtmosphereParameters::*quantity) {
    const std::vector<double> values = groupLaneValues(groups, quantity);
    Spectrum s(0.0f);
    for (int c = 0; c < kCieXyzChannels; ++c) {
      double mean = 0.0;
      for (size_t i = 0; i < values.size(); ++i) mean += sunlight_share_[c][i] * values[i];
      s[c] = static_cast<float>(mean);
    }
    return s;
  };
  a.ground_albedo = sunlightMean(&AtmosphereParameters::ground_albedo);
  a.rayleigh_scattering = sunlightMean(&AtmosphereParameters::rayleigh_scattering);
  a.mie_scattering = sunlightMean(&AtmosphereParameters::mie_scattering);
  a.mie_extinction = sunlightMean(&AtmosphereParameters::mie_extinction);
  a.absorption_extinction = sunlightMean(&AtmosphereParameters::absorption_extinction);
  const std::vector<double> sun = groupLaneValues(groups, &AtmosphereParameters::sun_irradiance);
  a.sun_irradiance = Spectrum(0.0f);
  for (int c = 0; c < kCieXyzChannels; ++c) {
    double integral = 0.0;
    for (size_t i = 0; i < sun.size(); ++i) integral += colour_matching_[c][i] * sun[i];
    a.sun_irradiance[c] = static_cast<float>(integral);
  }
  return a;
}

}  // namespace skybake::colour
