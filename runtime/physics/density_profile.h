// Density of a constituent at an altitude, relative to where its coefficients
// are quoted (density 1): the layer formula is the kernel
// runtime/kernel/density_profile.glsl, which the shaders share.
#pragma once

#include "data_formats/config/atmosphere_parameters.h"
#include "data_formats/kernel/kernel_language.h"

namespace skybake {
namespace kernel {
#include "runtime/kernel/density_profile.glsl"
}  // namespace kernel

// Dimensionless density in [0, 1] at altitude_m above the ground.
inline double layerDensity(const DensityLayer& layer, double altitude_m) {
  return kernel::skybakeLayerDensity(layer.exp_term, layer.exp_scale, layer.linear_term, layer.constant_term,
                                     altitude_m);
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
