// Scattering and extinction coefficients at an altitude: the constituents'
// coefficients at density 1 times their density profiles.
#pragma once

#include <glm/common.hpp>

#include "data_formats/config/atmosphere_parameters.h"
#include "runtime/physics/density_profile.h"

namespace skybake {

class AtmosphereMedia {
 public:
  explicit AtmosphereMedia(const AtmosphereParameters& a) : a_(a) {}

  double rayleighDensity(double altitude_m) const { return profileDensity(a_.rayleigh_density, altitude_m); }
  double mieDensity(double altitude_m) const { return profileDensity(a_.mie_density, altitude_m); }

  // Extinction coefficient, m^-1.
  SpectrumD extinction(double altitude_m) const {
    return SpectrumD(a_.rayleigh_scattering) * rayleighDensity(altitude_m) +
           SpectrumD(a_.mie_extinction) * mieDensity(altitude_m) +
           SpectrumD(a_.absorption_extinction) * profileDensity(a_.absorption_density, altitude_m);
  }

  // Extinction of the most attenuated channel, m^-1: what decides how finely
  // a ray must be integrated.
  double largestExtinction(double altitude_m) const { return largestChannel(extinction(altitude_m)); }
  // At least largestExtinction at any altitude, computed alike: every
  // density is at most 1 (density_profile.h), and a coefficient times a
  // density of at most 1 rounds to at most the coefficient.
  double largestExtinctionBound() const {
    return largestChannel(glm::abs(SpectrumD(a_.rayleigh_scattering)) + glm::abs(SpectrumD(a_.mie_extinction)) +
                          glm::abs(SpectrumD(a_.absorption_extinction)));
  }

  const AtmosphereParameters& parameters() const { return a_; }

 private:
  const AtmosphereParameters& a_;
};

}  // namespace skybake
