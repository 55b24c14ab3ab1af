// Phase functions, sr^-1, normalised to 1 over the sphere: the one definition
// of each, used by the bake, its density kernel, the lookups (scalar and
// batch) and the reference solver. nu is the cosine of the scattering angle
// (between the propagation directions before and after).
#pragma once

#include <cmath>

#include "data_formats/angles.h"

namespace skybake {

// Rayleigh: 3 / (16 pi) (1 + nu^2). The density kernel expands the shape
// (1 + nu^2) in Fourier modes itself and applies the normalisation after.
inline constexpr double kRayleighPhaseNormalisation = 3.0 / (16.0 * kPi);
inline double rayleighPhaseShape(double nu) { return 1.0 + nu * nu; }
inline double rayleighPhase(double nu) { return kRayleighPhaseNormalisation * rayleighPhaseShape(nu); }

// Cornette-Shanks: Henyey-Greenstein's shape with Rayleigh's (1 + nu^2), a
// better fit to Mie scattering by haze, with its constants for one g worked
// out once. |g| < 1 is guaranteed by validation, so the base
// 1 + g^2 - 2 g nu >= (1 - |g|)^2 > 0.
class CornetteShanksPhase {
 public:
  explicit CornetteShanksPhase(double g)
      : g_(g), normalisation_(3.0 / (8.0 * kPi) * (1.0 - g * g) / (2.0 + g * g)), one_plus_g2_(1.0 + g * g) {}

  double operator()(double nu) const {
    const double base = one_plus_g2_ - 2.0 * g_ * nu;
    return normalisation_ * rayleighPhaseShape(nu) / (base * std::sqrt(base));
  }
  // The phase function over its normalisation, for callers that apply it
  // once to many values (the density kernel's Fourier modes).
  double shape(double nu) const {
    const double base = one_plus_g2_ - 2.0 * g_ * nu;
    return rayleighPhaseShape(nu) / (base * std::sqrt(base));
  }
  double normalisation() const { return normalisation_; }

 private:
  double g_;
  double normalisation_;  // 3 / (8 pi) (1 - g^2) / (2 + g^2)
  double one_plus_g2_;
};

inline double cornetteShanksPhase(double g, double nu) { return CornetteShanksPhase(g)(nu); }

// Henyey-Greenstein, (1 - g^2) / (4 pi (1 + g^2 - 2 g nu)^1.5): not a phase
// the atmosphere uses, but the density the reference solver draws scattering
// directions from, since it can be sampled in closed form.
inline double henyeyGreensteinPhase(double g, double nu) {
  const double base = 1.0 + g * g - 2.0 * g * nu;
  return (1.0 - g * g) / (4.0 * kPi * base * std::sqrt(base));
}

}  // namespace skybake
