// Phase functions, sr^-1, normalised to 1 over the sphere. nu is the cosine of
// the scattering angle (between the propagation directions before and after).
#pragma once

#include <cmath>

#include "data_formats/angles.h"

namespace skybake {

inline double rayleighPhase(double nu) {
  constexpr double k = 3.0 / (16.0 * kPi);
  return k * (1.0 + nu * nu);
}

// Cornette-Shanks: Henyey-Greenstein's shape with Rayleigh's (1 + nu^2), a
// better fit to Mie scattering by haze. |g| < 1 is guaranteed by validation,
// so the base 1 + g^2 - 2 g nu >= (1 - |g|)^2 > 0.
inline double cornetteShanksPhase(double g, double nu) {
  const double k = 3.0 / (8.0 * kPi) * (1.0 - g * g) / (2.0 + g * g);
  const double base = 1.0 + g * g - 2.0 * g * nu;
  return k * (1.0 + nu * nu) / (base * std::sqrt(base));
}

}  // namespace skybake
