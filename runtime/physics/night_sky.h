// The sky for a sun below the lowest baked sun angle (sun.max_zenith_deg):
// the night continuation of the tables. Single scattering needs none (with
// the sun below the horizon it is integrated along each ray for any sun, see
// runtime/sky_twilight.cpp); what the tables give there, multiple scattering
// and the sky irradiance, is their value at the lowest baked sun scaled by
// NightContinuation::scale, which is 1 at that sun, falls with the sun's
// depression and reaches the night floor (0) where no sunlit air is left in
// reach of light scattered twice (darkSunZenithRad). The scale's formula is
// the kernel runtime/kernel/night_continuation.glsl, which the shaders share.
#pragma once

#include <algorithm>
#include <cmath>

#include "data_formats/angles.h"
#include "data_formats/bake_file/textures.h"
#include "data_formats/parameterization/ray_sphere.h"
#include "data_formats/parameterization/texture_mapping.h"
#include "data_formats/spectra/spectrum.h"

namespace skybake {
namespace kernel {
#include "runtime/kernel/night_continuation.glsl"
}  // namespace kernel

// What the sky gives with the sun far below the horizon. skybake models
// sunlight only (no airglow, starlight or moonlight), so the floor is 0: at
// the nadir sun every lookup from inside the atmosphere gives exactly this.
inline constexpr double kNightFloor = 0.0;

// The sun zenith angle (rad) beyond which no light scattered only once or
// twice reaches a camera inside the atmosphere: sunlit air at the top lies
// up to acos(bottom / top) beyond the terminator, and light from it reaches
// air up to 2 acos(bottom / top) further round the planet, which a camera
// sees from up to 2 acos(bottom / top) further still (both at the top).
// 121.4 deg for Earth; at most the nadir.
inline double darkSunZenithRad(double bottom_radius_m, double top_radius_m) {
  return std::min(0.5 * kPi + 4.0 * std::acos(bottom_radius_m / top_radius_m), kPi);
}

struct NightContinuation {
  // The lowest baked sun: zenith cosine and sine. Suns at or above it are
  // not continued (scale 1).
  double edge_mu_s = -1.0;
  double edge_sin = 0.0;
  // One over tan(span / 2), span being the depression (rad) from the edge to
  // where the scale reaches 0 (darkSunZenithRad, or the nadir where the edge
  // lies beyond it); 0 where nothing lies below the edge.
  double inverse_tan_half_span = 0.0;
  // Per channel, the power p of the scale (1 - tan(d / 2) / tan(span / 2))^p
  // at depression d below the edge: the tables' own fall-off there, so that
  // the sky goes on darkening at the rate it had, p = max(2 k tan(span / 2),
  // 1) with k the logarithmic fall-off of the ground's sky irradiance per
  // radian between the irradiance table's two lowest sun texels.
  Spectrum exponent{1.0f};

  // The share of the lowest baked sun's tabulated light left with the sun
  // at zenith cosine mu_s: 1 at and above the edge, non-increasing below it,
  // 0 from the dark zenith angle on (kernel::skybakeNightScaleBase).
  Spectrum scale(double mu_s) const { return mu_s >= edge_mu_s ? Spectrum(1.0f) : scaleBelowEdge(mu_s); }
  Spectrum scaleBelowEdge(double mu_s) const;
};

// The continuation of a bake's tables: its domain's lowest sun and the
// fall-off its irradiance table (`irradiance`, empty where the bake left it
// out: a linear fall to 0 then) has there.
NightContinuation nightContinuationOf(const AtmosphereDomain& domain, const Texture2D& irradiance);

}  // namespace skybake
