// Multiple-scattering tables are stored divided by a shape that depends on
// the texel's r and nu (runtime/physics/multiple_scattering_phase.h), a different one
// for each order while the bake iterates. These walk a table's texels with
// the nu each was computed for.
#pragma once

#include <array>
#include <vector>

#include "baker/stages/stage_context.h"
#include "data_formats/bake_file/textures.h"
#include "runtime/physics/multiple_scattering_phase.h"

namespace skybake {

// Which texels a 4D table holds: the scattering tables' (Bruneton's mu with
// the horizon split) or the stored density's (mu linear in [-1, 1]).
enum class TexelLayout { Scattering, Density };

// Mean radiance over each (r, mu_s) slice (every mu and nu) of a table
// stored divided by `shape`, the shape multiplied back (W m^-2 sr^-1 nm^-1):
// entry i_r * mu_s_size + i_mu_s.
std::vector<SpectrumD> sliceMeanShapedRadiance(const TableSampler& sampler, const Texture4D& table,
                                               const MultipleScatteringPhase& shape);

// sum += scale * delta * from / to at every texel: `delta` is divided by the
// shape `from`, `sum` by `to`.
void addReshaped(const TableSampler& sampler, TexelLayout layout, const Texture4D& delta,
                 const MultipleScatteringPhase& from, const MultipleScatteringPhase& to, const Spectrum& scale,
                 Texture4D& sum);

// The same with a scale per (r, mu_s) slice of the sampler's tables:
// slice_scale[i_r * mu_s_size + i_mu_s].
void addReshaped(const TableSampler& sampler, TexelLayout layout, const Texture4D& delta,
                 const MultipleScatteringPhase& from, const MultipleScatteringPhase& to,
                 const std::vector<Spectrum>& slice_scale, Texture4D& sum);

// sum[c] += sum over lanes l of mix[c][l] * delta[l] * from[l] / to[c] at
// every texel: a table of one set of channels divided by its shape `from`
// added, mixed linearly, into a table of other channels divided by `to` (a
// colour bake's wavelengths into X, Y, Z). Exact at the texels whatever the
// shapes are (the file's shape is multiplied back at the same r and nu).
void addMixedReshaped(const TableSampler& sampler, TexelLayout layout, const Texture4D& delta,
                      const MultipleScatteringPhase& from, const MultipleScatteringPhase& to,
                      const std::array<Spectrum, kMaxChannels>& mix, Texture4D& sum);

}  // namespace skybake
