// The bake file: one multi-part OpenEXR holding every table of a bake and,
// in `skybake:` header attributes, everything needed to use it. FORMAT.md is
// the specification.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "data_formats/bake_file/bake_file_attributes.h"
#include "data_formats/bake_file/multiple_shape_weight.h"
#include "data_formats/bake_file/textures.h"
#include "data_formats/config/atmosphere_parameters.h"
#include "data_formats/parameterization/texture_mapping.h"

namespace skybake {

// Bumped whenever the meaning of a part or attribute changes; readers refuse
// versions they do not know. Version 3 names the optical-depth part for what
// it holds and states everything a reader needs in typed attributes; version
// 4 states what the channels hold (skybake:channels: wavelengths or CIE XYZ);
// version 5 spreads the sun axis's texels split at the horizon
// (SunAxisMapping::SplitAtHorizon); version 6 stores HALF 4D parts scaled by
// a power of two per (r, mu_s) slice (half_slices.h), the density part
// included, and the irradiance always FLOAT; version 7 states the density
// part's own view (mu) size, which may be smaller than the other 4D parts';
// version 8 divides multiple scattering by a shape whose peak is thinned by
// the vertical scattering optical depth (MultipleShapeWeight); version 9
// spaces the irradiance rows by a cosine and blends them over the vertical
// optical depth above (IrradianceRows); version 10 gives a colour bake each
// wavelength's optical depth and coefficients (BakeContents::wavelength_groups,
// BakeFile::wavelength_optical_depth).
// Versions 2 to 9 (2 to 4 on Bruneton's sun axis; 2 and 3 always
// wavelengths) are still read (FORMAT.md, "Older versions").
inline constexpr int kBakeFormatVersion = 10;
// The first format version whose HALF 4D parts carry slice exponents.
inline constexpr int kFirstHalfSliceExponentsFormatVersion = 6;
// The first format version that states the density part's view size.
inline constexpr int kFirstDensityViewSizeFormatVersion = 7;
// The first format version whose multiple-scattering shape is thinned by the
// scattering depth.
inline constexpr int kFirstThinnedShapeFormatVersion = 8;
// The first format version whose irradiance rows are IrradianceRows::CosineOverDepth.
inline constexpr int kFirstCosineIrradianceRowsFormatVersion = 9;
// The first format version whose colour bakes state their wavelengths'
// optical depths and coefficients.
inline constexpr int kFirstWavelengthDepthFormatVersion = 10;
// The first format version whose sun axis is SunAxisMapping::SplitAtHorizon.
inline constexpr int kFirstSplitSunAxisFormatVersion = 5;

// The sun axis of a file of this format version.
inline SunAxisMapping sunAxisOfFormatVersion(int format_version) {
  return format_version >= kFirstSplitSunAxisFormatVersion ? SunAxisMapping::SplitAtHorizon
                                                           : SunAxisMapping::DistanceToTop;
}
// The irradiance rows of a file of this format version.
inline IrradianceRows irradianceRowsOfFormatVersion(int format_version) {
  return format_version >= kFirstCosineIrradianceRowsFormatVersion ? IrradianceRows::CosineOverDepth
                                                                   : IrradianceRows::Linear;
}
// The multiple-scattering shape of a file of this format version.
inline MultipleShapeWeight multipleShapeWeightOfFormatVersion(int format_version) {
  return format_version >= kFirstThinnedShapeFormatVersion ? MultipleShapeWeight::ThinnedByScatteringDepth
                                                           : MultipleShapeWeight::ColumnShare;
}
inline constexpr int kOldestReadBakeFormatVersion = 2;

struct BakeTables {
  // Optical depth (dimensionless) from (r, mu) to the top boundary, per channel.
  // Stored as optical depth rather than transmittance so that the transmittance
  // between two points is exp(-(difference)) and never 0/0 in thick atmospheres.
  Texture2D optical_depth;
  // Single Rayleigh scattering divided by the Rayleigh phase function:
  // W m^-2 nm^-1 (W m^-2 sr^-1 nm^-1 / sr^-1).
  Texture4D single_rayleigh;
  // Single Mie scattering divided by the Mie phase function; no texels where
  // the bake has no Mie scattering (bakeStoresSingleMie).
  Texture4D single_mie;
  // Scattering orders 2..N divided by the multiple-scattering shape at the
  // texel's r and own nu (runtime/physics/multiple_scattering_phase.h), W m^-2 nm^-1.
  Texture4D multiple_scattering;
  // Sky irradiance on a horizontal surface (direct sun excluded), W m^-2 nm^-1.
  Texture2D irradiance;
  // Light scattered once more per unit length at (r, mu_s) toward the viewer
  // looking along (mu, nu), summed over orders 2..N, divided like
  // multiple_scattering by the multiple-scattering shape: W m^-3 nm^-1. The
  // source of multiple scattering, which lets short segments (aerial
  // perspective) be integrated directly instead of as a difference of two
  // nearly equal lookups.
  Texture4D multiple_density;
};

// What a bake file states about its tables besides their texels: everything a
// reader needs to use them, each in typed header attributes (FORMAT.md). The
// config the bake was made from travels beside it as provenance only.
struct BakeContents {
  AtmosphereParameters atmosphere;
  TextureSizes sizes;       // the stored tables' sizes; `iteration` unset
  AtmosphereDomain domain;  // what the 4D tables cover
  SceneOutputs outputs;     // which optional parts the bake holds
  StoragePrecision precision = StoragePrecision::Float;
  // bake.stored_fraction_bits: the fraction bits the FLOAT values keep (all
  // for a file written without the attribute).
  int stored_fraction_bits = kFloatFractionBits;
  bool combined_single_mie = false;  // bake.combined_single_mie as the bake applied it
  // A spectral bake of more than kMaxChannels wavelengths (atmosphere
  // Spectral, FORMAT.md "Spectral bakes"): its wavelengths in groups of at
  // most kMaxChannels, in channel order, each an ordinary atmosphere of
  // those wavelengths. Empty otherwise.
  std::vector<AtmosphereParameters> lane_groups;
  // The multiple-scattering density table's view (mu) texels; its r, mu_s
  // and nu axes are the other 4D tables'. Its mu axis is linear in the view
  // cosine (densityCoordMu) and smooth, so it may hold fewer texels than
  // the radiance tables' (set by the baker; before format version 7, equal).
  int density_view_size = 0;
  // A colour bake's wavelengths in groups of at most kMaxChannels, in
  // wavelength order, each the ordinary atmosphere of those wavelengths its
  // pass was baked with (FORMAT.md "Colour bakes"): the runtime integrates
  // twilight single scattering per wavelength from them and
  // BakeFile::wavelength_optical_depth. Empty otherwise, and for colour
  // bakes read from files before kFirstWavelengthDepthFormatVersion.
  std::vector<AtmosphereParameters> wavelength_groups;
  // What multiple scattering and its density are stored divided by (set
  // from the format version when read).
  MultipleShapeWeight multiple_shape_weight = MultipleShapeWeight::ThinnedByScatteringDepth;
  bool operator==(const BakeContents&) const = default;

  // The density table's sizes: sizes with scattering_mu = density_view_size.
  TextureSizes densityTableSizes() const {
    TextureSizes s = sizes;
    s.scattering_mu = density_view_size;
    return s;
  }
};

// The version a file is written at: the current one, or for tables baked
// the way an older version stores them (a bake read from an older file and
// written again) the last version that stores them so, so that a reader
// decodes them as they were baked. Tables on Bruneton's sun axis predate
// the thinned shape, those with the unthinned shape the cosine rows, and a
// colour bake without its wavelengths' optical depths version 10.
inline int formatVersionToWrite(const BakeContents& contents) {
  const AtmosphereDomain& domain = contents.domain;
  if (domain.sun_axis != SunAxisMapping::SplitAtHorizon) return kFirstSplitSunAxisFormatVersion - 1;
  if (contents.multiple_shape_weight != MultipleShapeWeight::ThinnedByScatteringDepth)
    return kFirstThinnedShapeFormatVersion - 1;
  if (domain.irradiance_rows != IrradianceRows::CosineOverDepth) return kFirstCosineIrradianceRowsFormatVersion - 1;
  const bool without_wavelengths = contents.atmosphere.storesCieXyz() && contents.wavelength_groups.empty();
  return without_wavelengths ? kFirstWavelengthDepthFormatVersion - 1 : kBakeFormatVersion;
}

// The contents of a bake of `config` whose 4D tables cover `domain`.
BakeContents storedContents(const BakeConfig& config, const AtmosphereDomain& domain);

// Calls fn(part name, texels) for every table of a bake, in the file's part
// order: the one list of tables that code walking all of them uses, so that a
// table added later is not missed.
template <typename Tables, typename Fn>
void forEachTable(Tables& t, Fn&& fn) {
  fn(bake_file::kPartOpticalDepth, t.optical_depth.texels);
  fn(bake_file::kPartSingleRayleigh, t.single_rayleigh.texels);
  fn(bake_file::kPartSingleMie, t.single_mie.texels);
  fn(bake_file::kPartMultipleScattering, t.multiple_scattering.texels);
  fn(bake_file::kPartIrradiance, t.irradiance.texels);
  fn(bake_file::kPartMultipleDensity, t.multiple_density.texels);
}

// Whether a bake stores the `single_mie` part: not when no channel has Mie
// scattering, where it would hold nothing but zeros (a quarter of the file).
// Readers then leave BakeTables::single_mie without texels.
inline bool bakeStoresSingleMie(const AtmosphereParameters& a) {
  for (int c = 0; c < a.laneCount(); ++c) {
    if (a.mie_scattering[c] > 0.0f) return true;
  }
  return false;
}
// The same for a file: a spectral bake stores the part when any of its lane
// groups has Mie scattering (the others' channels hold zeros there).
bool bakeStoresSingleMie(const BakeContents& contents);

// That channel's name: "mie_" and the first wavelength's channel name.
std::string combinedSingleMieChannelName(const AtmosphereParameters& a);

// Rebuilds single Mie scattering in every channel from its first channel,
// assuming that Mie and Rayleigh single scattering (phase functions divided
// out) share their spectral shape up to the ratio of the scattering
// coefficients: mie[c] = rayleigh[c] * mie[0] / rayleigh[0] * (beta_R[0] /
// beta_M[0]) * (beta_M[c] / beta_R[c]). Exact where the light reaching the
// scattering points is attenuated alike at every wavelength; otherwise off
// by the difference in attenuation along the Rayleigh and Mie paths (largest
// near the sun at low elevations, docs/LEAVE_OUT.md). The first channel is
// kept as it is; where rayleigh[0] is 0 (no light) the others are 0.
void approximateSingleMie(const AtmosphereParameters& a, const Texture4D& rayleigh, Texture4D& mie);

// A part that a bake leaves out of its file: the scene does not use it
// ([scene] outputs) or it would hold only zeros.
struct LeftOutPart {
  const char* part;    // its name (FORMAT.md)
  const char* reason;  // why, in words
  uint64_t bytes;      // what leaving it out saves, uncompressed
};
std::vector<LeftOutPart> leftOutParts(const BakeContents& contents);
bool leavesOut(const BakeContents& contents, const char* part);
// Empties the texels of the tables a bake leaves out (their sizes stay); a
// single Mie table stored combined becomes what a reader rebuilds from the
// file (approximateSingleMie), so in-memory and read-back bakes agree.
void clearLeftOutTables(const BakeContents& contents, BakeTables& tables);
// The tables as the file stores them, so in-memory and read-back bakes
// agree to the bit: every table but the optical depths rounded to
// contents.stored_fraction_bits (FORMAT.md "Stored precision"), then the
// left-out tables cleared (clearLeftOutTables, whose rebuilt single Mie
// comes from the rounded values, as a reader's does).
void settleStoredTables(const BakeContents& contents, BakeTables& tables);

struct BakeFile {
  BakeContents contents;  // what the tables hold and cover; sizes equal the tables' sizes
  // Provenance: the settled config the bake was made from, canonical TOML
  // (configToToml). Readers do not parse it; tools that report how a bake
  // was made (skybake info) may.
  std::string config_toml;
  int orders_computed = 0;  // scattering orders in the tables
  // The version the file was read from (readBakeFile); files are always
  // written at kBakeFormatVersion.
  int format_version = kBakeFormatVersion;
  std::string report_json;  // the bake report, JSON text (opaque here)
  // Every table, lanes in channel order. Empty for a spectral bake of more
  // than kMaxChannels wavelengths, whose tables are lane_group_tables.
  BakeTables tables;
  // A spectral bake's tables per lane group (contents.lane_groups), each
  // what an ordinary bake of that group's wavelengths holds: multiple
  // scattering divided by the group's own shape. Empty otherwise.
  std::vector<BakeTables> lane_group_tables;
  // A colour bake's optical depth per wavelength group
  // (contents.wavelength_groups), each what an ordinary bake of that group
  // holds in BakeTables::optical_depth. Empty otherwise.
  std::vector<Texture2D> wavelength_optical_depth;
};

// The number of lane groups of a bake: 1, or a spectral bake's groups.
inline size_t laneGroupCount(const BakeContents& contents) {
  return contents.lane_groups.empty() ? 1 : contents.lane_groups.size();
}
// Lane group g of a spectral bake (0 of any other) as the ordinary bake of
// its wavelengths: the contents an ordinary bake of that atmosphere states,
// the group's tables, and the file's config, orders and report. `spectral`
// is left without that group's tables.
BakeFile takeLaneGroup(BakeFile& spectral, size_t g);

// Writes atomically: a temporary file beside `path`, renamed into place once
// complete. On failure no file is left behind and an existing `path` is intact.
// `before_rename`, if given, is called with the complete temporary file just
// before the rename, for outputs that belong with it (a report beside it): if
// it throws, the existing `path` stays as it was. Throws Error(BadInput) for
// an unwritable destination (see atomic_file.h), Error(Internal) otherwise.
void writeBakeFile(const std::filesystem::path& path, const BakeFile& bake,
                   const std::function<void(const std::filesystem::path& temp)>& before_rename = {});

// The threads OpenEXR compresses a written file's line blocks on (its global
// thread pool, which it leaves empty: one thread). ZIP is most of a write's
// time, about 3.4 s of the default bake's on one core and 1.8 s on two; the
// bytes written are the same for any count. 0 compresses on the calling thread.
void setBakeFileWriteThreads(int threads);

// Reads a bake back, every attribute included. Throws Error(BadInput) naming
// the file and the reason for a missing, truncated, corrupt, foreign or
// unknown-version file, and for one whose header promises more table data
// than a file of its size can hold; Error(Internal) if memory runs out.
BakeFile readBakeFile(const std::filesystem::path& path);

// The same checks of every header, part and attribute, without the tables:
// its tables have their sizes and no texels. For tools that print what a
// bake holds (skybake info): a few milliseconds whatever the file's size,
// where reading the default bake's tables takes over a second.
BakeFile readBakeFileHeader(const std::filesystem::path& path);

// The same from a bake already in memory (`bytes` is the whole file);
// `source_name` stands for the file in error messages.
BakeFile readBakeFileFromMemory(std::span<const std::byte> bytes, const std::string& source_name);

// Channel name in the file for a wavelength: "680nm", "532p5nm" ('.' is the
// EXR layer separator, so fractions use 'p').
std::string channelName(double wavelength_nm);

// The names of a bake's channels in the file, in channel order: each
// wavelength's channelName, or "X", "Y", "Z" for a colour bake.
std::vector<std::string> channelNames(const AtmosphereParameters& a);

}  // namespace skybake
