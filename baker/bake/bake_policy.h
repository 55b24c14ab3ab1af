// How a bake settles its config before it starts: which scene ranges are
// worth narrowing the tables to, and the sizes the orders iterate on. Bake
// policy, not parameterization: readers never need it, since the file states
// the domain it covers (data_formats/FORMAT.md).
#pragma once

#include "data_formats/bake_file/bake_file.h"
#include "data_formats/config/atmosphere_parameters.h"
#include "data_formats/parameterization/texture_mapping.h"

namespace skybake {

// The domain a config's 4D tables cover: its [scene] ranges, the sun range
// widened by a margin each side and its low end moved so that a texel sits on
// the horizon; the whole domain without them. The file states the result
// (FORMAT.md), so readers never recompute it.
AtmosphereDomain sceneDomain(const BakeConfig& config);

// The sizes the bake's orders iterate on: the stored ones, except that a
// scene that narrows the domain iterates over the whole domain at
// resolution.iteration (default: the default scattering sizes).
TextureSizes iterationTextureSizes(const BakeConfig& config);

// The sizes each order's radiance is computed on while the orders iterate
// (baker/bake/bake.cpp): the iteration sizes with half the view (mu) texels
// and three quarters of the view-sun (nu) texels, rounded up. That radiance
// only feeds the next order's density, an integral over every direction
// that smooths it; the stored multiple scattering is integrated once, on
// the iteration sizes, from every order's density. The altitude and sun
// axes stay, so its slices are the stored tables' (the per-slice
// convergence and tail read them). Half the view-sun texels put +1.8 % on
// astronomical twilight's mean at 550 and 440 nm (docs/MEASUREMENTS.md,
// "Orders on coarser tables").
TextureSizes orderRadianceSizes(const TextureSizes& iteration);

// The texels the orders compute their scattering density on, and the file
// stores it on (BakeContents::density_view_size): half the view axis
// (orderRadianceSizes'), every other axis kept. The density is an integral
// over every direction of the light arriving at a point, smooth in the view
// direction, and its view axis is linear in mu: read on these texels, every
// figure of the built-in Earth moves by at most 0.06 % RMS against density
// on the radiance tables' view texels (docs/MEASUREMENTS.md, "The density
// on half the view axis").
TextureSizes densitySizes(const TextureSizes& iteration);

// The config as the bake uses and stores it: a sun range that would add less
// than a texel's worth of resolution to the sun axis is dropped (the tables
// keep the whole axis, on the iteration's own sun texels), and a scene that
// narrows the domain gets its resolution.iteration written out: the default
// scattering sizes, with the stored tables' mu_s where the sun axis stays
// whole and that is larger, so that the stored tables' sun texels are the
// iteration's. A colour bake's atmosphere gets its X, Y, Z quantities from
// its wavelength groups (runtime/colour/colour_bake_weights.h).
// bakeAtmosphere settles its config this way.
BakeConfig settledBakeConfig(BakeConfig config);

// What the file of a bake of `settled` (settledBakeConfig) states about its
// tables: storedContents with sceneDomain, the density on densitySizes'
// view texels unless the scene narrows the domain.
BakeContents bakeContents(const BakeConfig& settled);

}  // namespace skybake
