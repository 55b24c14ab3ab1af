// Density of a constituent at an altitude, relative to where its coefficients
// are quoted (density 1). See DensityLayer for the layer formula.
#pragma once

#include <algorithm>
#include <cmath>

#include "data_formats/atmosphere_parameters.h"

namespace skybake {

// Dimensionless density in [0, 1] at altitude_m above the ground.
inline double layerDensity(const DensityLayer& layer, double altitude_m) {
  const double value =
      layer.exp_term * std::exp(layer.exp_scale * altitude_m) + layer.linear_term * altitude_m + layer.constant_term;
  return std::clamp(value, 0.0, 1.0);
}

// Layers stack from the ground up; the last one reaches the top whatever its width.
inline double profileDensity(const DensityProfile& profile, double altitude_m) {
  double layer_bottom_m = 0.0;
  for (size_t i = 0; i < profile.size(); ++i) {
    const double layer_top_m = layer_bottom_m + profile[i].width_m;
    if (i + 1 == profile.size() || altitude_m < layer_top_m) {
      return layerDensity(profile[i], altitude_m);
    }
    layer_bottom_m = layer_top_m;
  }
  return 0.0;
}

}  // namespace skybake
