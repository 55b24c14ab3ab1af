// The tables a bake keeps as its file stores them (bake_file.h).
#include "bake_file.h"
#include "stored_float_bits.h"

namespace skybake {
namespace {

void roundTexels(std::vector<Spectrum>& texels, int fraction_bits) {
  for (Spectrum& texel : texels) {
    for (int c = 0; c < kMaxChannels; ++c) texel[c] = roundToFractionBits(texel[c], fraction_bits);
  }
}

}  // namespace

void settleStoredTables(const BakeContents& contents, BakeTables& tables) {
  // The optical depths keep every bit: a transmittance exp(-depth) would
  // multiply their rounding by the depth, and their 2D table is too small
  // for its size to matter.
  for (std::vector<Spectrum>* texels :
       {&tables.single_rayleigh.texels, &tables.single_mie.texels, &tables.multiple_scattering.texels,
        &tables.irradiance.texels, &tables.multiple_density.texels}) {
    roundTexels(*texels, contents.stored_fraction_bits);
  }
  clearLeftOutTables(contents, tables);
}

}  // namespace skybake
