// The 4D tables' values across the sun (mu_s) axis below the horizon, stored
// for the blend the twilight lookups make between two mu_s texels.
//
// With the sun below the horizon a lookup blends two mu_s texels
// geometrically where they differ steeply (table_weights.glsl,
// skybakeBlendGeometricWhereSteep): linear in the logarithm. The logarithm of
// the twilight sky falls faster and faster as the sun sinks (a concave
// function of the sun's depression), so that blend reads low between texels:
// about -1 % at 440 nm from the ground at sun 92 to 95 deg at the default
// sizes, growing to -4 % in astronomical twilight. As altitude_prefilter.h
// does across r for a linear blend, each interior texel below the horizon is
// stored less a twelfth of its second difference, taken in the logarithm
// where the blend is geometric and in the value where it is linear (in
// proportion to the blend's own geometric share), so that the blend's mean
// error over each interval vanishes to second order in the spacing. Texels
// at or above the horizon (day lookups blend them linearly, and the horizon
// texel is shared by both) and the lowest sun's keep their values.
#pragma once

#include <vector>

#include "data_formats/bake_file/textures.h"

namespace skybake {

// The largest share of a texel's own value its correction may take: where
// the second difference is not a smooth curvature (the edge of the night, a
// texel that falls to zero) the formula would swing the texel far from its
// value.
inline constexpr float kMaxSunPrefilterShare = 0.25f;

// Replaces every texel of `table` whose sun cosine (texel_mu_s[i_mu_s], the
// texels' centres) is below zero, save the first, by its prefiltered value,
// every channel on its own.
void prefilterAcrossSunBelowHorizon(Texture4D& table, const std::vector<double>& texel_mu_s);

}  // namespace skybake
