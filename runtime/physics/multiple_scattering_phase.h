// The angular shape that multiple scattering is stored divided by.
//
// The 4D tables cannot follow a peak in the view-sun angle nu: where the view
// lies in the sun's vertical plane (every zenith view, every view toward or
// away from the sun) nu sits at the end of its allowed range, so the table
// holds that value only at texels whose mu and mu_s put it there, and
// interpolating in mu or mu_s crosses the peak. Single Mie scattering is
// stored divided by its phase function for this reason. Multiple scattering
// in hazy air has a peak of its own: light scattered twice forward by
// Cornette-Shanks g keeps roughly the shape of g^2 (for Henyey-Greenstein the
// convolution is exact), and in a Mie x100 haze the second order at the
// zenith was 2.3 times too bright interpolated linearly (the value at the
// texels was right).
//
// Multiple scattering and its source density are therefore stored divided by
//   f(r, nu) = (1 - w(r)) / (4 pi) + w(r) CS(g_ms, nu),    per channel,
// at the texel's r and at the nu the texel was computed for (clamped to what
// its mu and mu_s allow); a lookup multiplies by f at the looked-up r and nu.
// g_ms = g^2 (clamped), the second order's peak. The peak weight is
//   w(r) = m_local(r) m_column^2,
// m_local the Mie share of scattering at r and m_column the Mie share of the
// vertical scattering optical depth: a forward peak survives only where the
// last scattering is Mie's (m_local) and the light it scatters came through
// Mie scattering too, as the aureole (about m_column^2 of it once the broad
// Rayleigh sky and the ground are counted; the exponent is fitted, below).
// The rest is broad and smooth and interpolates best as it is (a constant
// divisor). Where the column is not optically thin the diffuse light has
// mostly been scattered more than twice, each time broadening the peak, and
// the peak's share falls with the vertical scattering optical depth tau_s:
// w is multiplied by max(1 - tau_s, 0) (MultipleShapeWeight::
// ThinnedByScatteringDepth, per channel). That factor is 0.95 / 0.89 / 0.73
// at 680 / 550 / 440 nm for the clear Earth, whose weight is tiny anyway
// (Mie's column share 0.09 to 0.02), and about 0.5 for Mars's dust, where
// the unthinned weight read the day sky near the horizon 4.75 % off at
// 680 nm (0.83 % thinned; docs/MEASUREMENTS.md, "The thinned shape
// shipped").
//
// Of the weights tried, m_local m_column^2 interpolates best for both clear
// Earth and a thick haze (docs/MEASUREMENTS.md, "Multiple-scattering
// shape"): a constant weight puts a peaked divisor above the haze layer,
// where the last scattering is Rayleigh's, and too much weight where the
// field is broad costs accuracy there. The peak must be divided at the texel's own
// nu: wherever nu is clamped (every zenith view, every view in the sun's
// vertical plane) the texel holds the peak's value at that nu. Values at
// texels are exact whatever f is; f only decides how well values between them
// interpolate. The baker and the runtime derive f from the atmosphere
// parameters stored in the file.
#pragma once

#include <algorithm>
#include <cmath>

#include "data_formats/bake_file/multiple_shape_weight.h"
#include "data_formats/config/atmosphere_parameters.h"
#include "data_formats/kernel/kernel_language.h"
#include "data_formats/spectra/spectrum.h"
#include "runtime/physics/density_profile.h"
#include "runtime/physics/phase_functions.h"

namespace skybake {
namespace kernel {
#include "runtime/kernel/multiple_scattering_shape.glsl"
}  // namespace kernel

// The largest |g_ms|. A divisor peaked more sharply than the tables' nu and
// mu_s spacing can follow makes interpolation error near the sun worse, not
// better: a texel computed right at the peak holds a tiny stored value and
// its neighbour off the peak a large one, and the lookup multiplies their
// blend by the peak. At 0.7 the divisor spans a factor of about 180 over
// all nu (the Mie x100 haze's g^2 = 0.64: 95).
inline constexpr double kMaxMultipleScatteringG = 0.7;

// Pieces of the midpoint rule for the vertical optical depths that set the
// Mie share. The share only weights the divisor's shape, so 1e-3 relative
// accuracy is far more than needed; 4096 pieces resolve scale heights down to
// a few pieces' width (15 m in a 60 km shell).
inline constexpr int kColumnDepthPieces = 4096;

// The order whose shape the stored tables are divided by: the second, the
// brightest and most peaked of the multiple-scattering orders.
inline constexpr int kStoredShapeOrder = 2;

class MultipleScatteringPhase {
 public:
  // The shape of scattering order `order` (>= 2): g_ms = g^order and
  // w = m_local m_column^order, a peak that each further Mie event widens and
  // each Rayleigh event weakens. The stored tables use kStoredShapeOrder; the
  // bake divides each order by its own shape while iterating (a higher order
  // divided by the second's peak came out too bright toward the sun, and
  // feeding that into the next order made light: in a Mie x1000 haze the
  // orders decayed by 0.95 each where single-scattering albedo 0.9 allows at
  // most 0.9).
  // `weight` is the file's (BakeContents::multiple_shape_weight) for a
  // stored shape; new bakes use the default.
  explicit MultipleScatteringPhase(const AtmosphereParameters& a, int order = kStoredShapeOrder,
                                   MultipleShapeWeight weight = MultipleShapeWeight::ThinnedByScatteringDepth)
      : g_(std::clamp(std::pow(a.mie_phase_g, order), -kMaxMultipleScatteringG, kMaxMultipleScatteringG)),
        order_(order),
        rayleigh_scattering_(a.rayleigh_scattering),
        mie_scattering_(a.mie_scattering),
        rayleigh_density_(a.rayleigh_density),
        mie_density_(a.mie_density) {
    const double thickness_m = a.top_radius_m - a.bottom_radius_m;
    const double piece_m = thickness_m / kColumnDepthPieces;
    double rayleigh_column_m = 0.0, mie_column_m = 0.0;  // integrals of density over altitude
    for (int i = 0; i < kColumnDepthPieces; ++i) {
      const double altitude_m = (i + 0.5) * piece_m;
      rayleigh_column_m += profileDensity(rayleigh_density_, altitude_m) * piece_m;
      mie_column_m += profileDensity(mie_density_, altitude_m) * piece_m;
    }
    column_mie_share_ = mieShare(rayleigh_column_m, mie_column_m);
    column_mie_share_power_ = SpectrumD(1.0);
    for (int i = 0; i < order; ++i) column_mie_share_power_ *= column_mie_share_;
    if (weight == MultipleShapeWeight::ThinnedByScatteringDepth) {
      for (int c = 0; c < kMaxChannels; ++c) {
        const double scattering_depth = rayleigh_scattering_[c] * rayleigh_column_m + mie_scattering_[c] * mie_column_m;
        column_mie_share_power_[c] *= std::max(1.0 - scattering_depth, 0.0);
      }
    }
  }

  // w at an altitude, per channel, in [0, 1].
  SpectrumD peakWeightAt(double altitude_m) const {
    return mieShare(profileDensity(rayleigh_density_, altitude_m), profileDensity(mie_density_, altitude_m)) *
           column_mie_share_power_;
  }

  // f for a peak weight w (from peakWeightAt) at nu, per channel, sr^-1;
  // always > 0.
  Spectrum operator()(const SpectrumD& peak_weight, double nu) const { return withPeak(peak_weight, peakAt(nu)); }

  // The same in two steps, for loops where nu is fixed and the weight varies.
  double peakAt(double nu) const { return cornetteShanksPhase(g_, nu); }
  static Spectrum withPeak(const SpectrumD& peak_weight, double peak) {
    Spectrum f(0.0f);
    for (int c = 0; c < kMaxChannels; ++c) {
      f[c] = static_cast<float>(kernel::skybakeMultipleShapeWithPeak(peak_weight[c], peak));
    }
    return f;
  }
  // The broad part: isotropic, sr^-1.
  static constexpr double kBroad = SKYBAKE_BROAD_PHASE;

  Spectrum operator()(double altitude_m, double nu) const { return (*this)(peakWeightAt(altitude_m), nu); }

  double g() const { return g_; }
  int order() const { return order_; }

 private:
  // Mie's share of scattering, per channel, for the given amounts (densities
  // or their integrals) of each constituent (kernel::skybakeMieShare).
  SpectrumD mieShare(double rayleigh_amount, double mie_amount) const {
    SpectrumD share(0.0);
    for (int c = 0; c < kMaxChannels; ++c) {
      share[c] = kernel::skybakeMieShare(rayleigh_scattering_[c] * rayleigh_amount, mie_scattering_[c] * mie_amount);
    }
    return share;
  }

  double g_;
  int order_;
  Spectrum rayleigh_scattering_, mie_scattering_;
  DensityProfile rayleigh_density_, mie_density_;
  SpectrumD column_mie_share_{0.0};
  SpectrumD column_mie_share_power_{0.0};  // m_column^order, thinned (MultipleShapeWeight)
};

}  // namespace skybake
