// Phase functions, sr^-1, normalised to 1 over the sphere: the kernel
// runtime/kernel/phase_functions.glsl in double, the one definition of each
// that the bake, its density kernel, the lookups (scalar, batch and GLSL)
// and the reference solver use. nu is the cosine of the scattering angle
// (between the propagation directions before and after).
#pragma once

#include <cmath>

#include "data_formats/angles.h"
#include "data_formats/kernel/kernel_language.h"

namespace skybake {
namespace kernel {
#include "runtime/kernel/phase_functions.glsl"
}  // namespace kernel

// Rayleigh: 3 / (16 pi) (1 + nu^2).
inline constexpr double kRayleighPhaseNormalisation = SKYBAKE_RAYLEIGH_PHASE_NORMALISATION;
inline constexpr auto& rayleighPhaseShape = kernel::skybakeRayleighPhaseShape;
inline constexpr auto& rayleighPhase = kernel::skybakeRayleighPhase;

// Cornette-Shanks for one g, its normalisation worked out once.
class CornetteShanksPhase {
 public:
  explicit CornetteShanksPhase(double g) : g_(g), normalisation_(kernel::skybakeCornetteShanksNormalisation(g)) {}

  double operator()(double nu) const { return kernel::skybakeCornetteShanksPhase(g_, normalisation_, nu); }
  // The phase function over its normalisation, for callers that apply it
  // once to many values (the density kernel's Fourier modes).
  double shape(double nu) const { return kernel::skybakeCornetteShanksShape(g_, nu); }
  double normalisation() const { return normalisation_; }

 private:
  double g_;
  double normalisation_;
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
