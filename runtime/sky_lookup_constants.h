// The constants of the Sky lookups that a second implementation of them
// (the GLSL of runtime/glsl/, which receives them as generated defines from
// runtime/gl/) must share: each with what it is for, in one place.
#pragma once

namespace skybake {

// ---- single scattering with the sun below the horizon (sky_twilight.cpp) ----

// From the horizon up to this sun elevation (as a zenith cosine, sin 1 deg)
// the integral's weight falls smoothly from 1 to 0, so no step shows as the
// sun sets; the tables are within 1 % of the integral there.
inline constexpr double kIntegratedSingleScatteringTopCosine = 0.0175;
// Sub-intervals of 4 Gauss nodes over the ray for that integral (the bake
// uses 8): 0.12 % RMS of the sky radiance off a 64-sub-interval rule on a
// grid of twilight views, at about 6 times a day lookup's cost
// (docs/MEASUREMENTS.md).
inline constexpr int kLookupSingleScatteringSegments = 4;

// ---- solar eclipses (sky_eclipse.cpp) ----

// Sub-intervals of 4 Gauss nodes over the view ray for single scattering
// under an eclipse, integrated with and without the moon (their ratio scales
// the uneclipsed lookup). The moon's shadow ends in a penumbra thousands of
// kilometres wide, smooth along any ray, and its umbra (a hundred
// kilometres or so) has soft edges; 16 sub-intervals put several nodes
// across the umbra of a ray crossing it near the ground.
inline constexpr int kEclipseSingleScatteringSegments = 16;

// Below this share of the uneclipsed single scattering, the ratio of the
// eclipsed to the plain integral is taken as the eclipsed integral alone: a
// sun already set along the whole ray leaves both at rounding level, whose
// ratio is noise. Float keeps 1e-30 normal, so the GLSL uses it too.
inline constexpr float kEclipseSmallestUneclipsedSingle = 1e-30f;

// The sky irradiance's directions under an eclipse: cosine-weighted over
// the hemisphere, kEclipseIrradianceBands bands of equal weight in the
// zenith angle's sine squared times kEclipseIrradianceAzimuths azimuths. The
// plain and the eclipsed sky are summed over the same directions and only
// their ratio is used, so the rule's error (the sky near the sun, the
// horizon's glow) largely cancels; 48 directions put one about every 30 deg.
inline constexpr int kEclipseIrradianceBands = 6;
inline constexpr int kEclipseIrradianceAzimuths = 8;

// ---- rays toward the ground of a bake without such views (sky_radiance.cpp) ----

// A bake whose tables hold no rays toward the ground ([scene]
// views_below_horizon = false) integrates such a ray at each lookup: single
// scattering as twilight lookups do, multiple scattering from its tabulated
// density, over this many sub-intervals of 4 Gauss nodes (more changed no
// validated figure: docs/MEASUREMENTS.md).
inline constexpr int kGroundRaySubintervals = 4;

// ---- radiance to a point (sky_radiance_to_point.cpp) ----

// Below this sun elevation cosine, single Mie scattering toward a point is
// faded out: the difference of two Mie lookups at neighbouring twilight
// texels is noise larger than the signal (Bruneton 2017 does the same).
inline constexpr double kMieTwilightFadeCosine = 0.01;
// Half-width, in view zenith cosine, of the band around the geometric horizon
// where radiance to a point blends the ground-ray and sky-ray halves of the
// table. Each half is interpolated separately, so at the horizon the two
// estimates of the same segment integral differ by interpolation error; the
// blend removes that step. 0.002 is about 0.1 deg, a few texels of the mu axis
// near the horizon at the default 128.
inline constexpr double kHorizonBlendCosine = 0.002;
// Radiance toward a point is found two ways. Over long segments, as the
// scattering to the ray's end seen from the camera minus that seen from the
// point (two lookups). Over short ones that difference is a few percent of
// either term, so the tables' interpolation kinks, amplified 30 to 100 times,
// show as seams; there the segment is integrated directly from the
// single-scattering source and the tabulated multiple-scattering source.
// Between the two lengths the results are blended linearly in distance.
// With the sun below the horizon every segment is integrated directly, as
// single scattering along whole rays is: the tables' difference is further
// off there (docs/MEASUREMENTS.md).
inline constexpr double kDirectSegmentMaxLength_m = 20000.0;
inline constexpr double kDifferenceSegmentMinLength_m = 10000.0;
// 4 sub-intervals x 4 Gauss nodes: a vertical 20 km segment holds 17 Mie
// scale heights, 4 per sub-interval, integrated to ~1e-3.
inline constexpr int kDirectSegmentSubintervals = 4;

// ---- transmittance along a segment (sky_transmittance.cpp) ----

// A ray whose closest approach to the planet centre lies within this distance
// below the ground only grazes it. Points along an exactly tangent ray give
// directions that differ by rounding (~1e-16 rad), so the same ray was
// classified as hitting the ground or not from one point to the next, and the
// transmittance to points past the tangent point flickered between 0 and its
// value. 1 mm is far above that rounding (~1e-6 m at 1e10 m) and far below
// any geometry a renderer resolves.
inline constexpr double kGroundGrazeTolerance_m = 1e-3;

}  // namespace skybake
