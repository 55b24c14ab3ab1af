// The tables a bake keeps as its file stores them (bake_file.h).
#include "data_formats/bake_file/bake_file.h"
#include "data_formats/bake_file/half_slices.h"
#include "data_formats/bake_file/stored_float_bits.h"

namespace skybake {
namespace {

void roundTexels(std::vector<Spectrum>& texels, int fraction_bits) {
  for (Spectrum& texel : texels) {
    for (int c = 0; c < kMaxChannels; ++c) texel[c] = roundToFractionBits(texel[c], fraction_bits);
  }
}

// A 4D table rounded as a half file stores it. `first_lane_beside`, if
// given, is a table whose first lane the same part stores (a combined single
// Mie channel): rounded with the part's exponents too.
void roundToScaledHalf(Texture4D& table, std::vector<Spectrum>* first_lane_beside = nullptr) {
  std::vector<HalfSliceLanes> lanes = {{&table.texels, kMaxChannels}};
  if (first_lane_beside != nullptr) lanes.push_back({first_lane_beside, 1});
  const HalfSliceLayout layout = HalfSliceLayout::of(table);
  const std::vector<int> exponents = halfSliceExponents(layout, lanes);
  roundToScaledHalf(layout, exponents, table.texels, kMaxChannels);
  if (first_lane_beside != nullptr) roundToScaledHalf(layout, exponents, *first_lane_beside, 1);
}

}  // namespace

void settleStoredTables(const BakeContents& contents, BakeTables& tables) {
  // The optical depths keep every bit: a transmittance exp(-depth) would
  // multiply their rounding by the depth, and their 2D table is too small
  // for its size to matter. The irradiance, as small, is always FLOAT.
  roundTexels(tables.irradiance.texels, contents.stored_fraction_bits);
  if (contents.precision == StoragePrecision::Half) {
    // A combined bake stores single Mie's first lane in the single Rayleigh
    // part, with that part's exponents; its single Mie part is not written.
    if (contents.combined_single_mie) {
      roundToScaledHalf(tables.single_rayleigh, &tables.single_mie.texels);
    } else {
      roundToScaledHalf(tables.single_rayleigh);
      roundToScaledHalf(tables.single_mie);
    }
    roundToScaledHalf(tables.multiple_scattering);
    roundToScaledHalf(tables.multiple_density);
  } else {
    for (std::vector<Spectrum>* texels : {&tables.single_rayleigh.texels, &tables.single_mie.texels,
                                          &tables.multiple_scattering.texels, &tables.multiple_density.texels}) {
      roundTexels(*texels, contents.stored_fraction_bits);
    }
  }
  clearLeftOutTables(contents, tables);
}

}  // namespace skybake
