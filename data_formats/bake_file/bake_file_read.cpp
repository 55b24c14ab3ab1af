// Bake file reader. Trusts nothing in the file: OpenEXRCore checks the
// headers before OpenEXR's C++ reader parses them (exr_header_check.h), every
// part, channel, size and attribute is checked against the config carried in
// the header before a table is allocated or filled, and any OpenEXR failure
// becomes an Error naming the file. Files and memory buffers share this one
// reader through OpenEXR's stream interface.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatVectorAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputPart.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMultiPartInputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>
#include <fmt/format.h>

#include "data_formats/bake_file/bake_file.h"
#include "data_formats/bake_file/bake_file_attributes.h"
#include "data_formats/bake_file/bake_file_contents.h"
#include "data_formats/bake_file/exr_header_check.h"
#include "data_formats/bake_file/exr_memory_stream.h"
#include "data_formats/bake_file/half_slices.h"
#include "data_formats/bake_file/table_values.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"
#include "data_formats/input_file.h"
#include "data_formats/parameterization/texture_mapping.h"

namespace skybake {
namespace {

using namespace bake_file;

// The most bytes of uncompressed pixel data one byte of an OpenEXR file can
// hold. deflate (ZIP, the compression FORMAT.md specifies) cannot exceed
// 1032:1; PXR24 puts at most 4:3 in front of deflate (1376:1), and OpenEXR's
// other codecs (RLE 64:1, PIZ, B44, and DWA, which stores channels named as
// skybake names them losslessly with deflate) stay below that. A header whose
// table sizes need more data than the file could hold is corrupt, and is
// refused before gigabytes are allocated for a small file.
constexpr uint64_t kMaxExrExpansion = 2048;

uint64_t pixelBytes(Imf::PixelType type) { return type == Imf::HALF ? 2 : 4; }

// A part found in the file and checked against the table it must hold.
struct PartLayout {
  const char* name = nullptr;
  int index = 0;
  int width = 0;
  int height = 0;
  uint64_t stored_bytes = 0;  // its channels' pixel data, uncompressed
  std::string extra_channel;  // read into the first lane of other texels (combined single Mie), or ""
  // A HALF 4D part's slice layout and exponents (half_slices.h); empty
  // exponents for FLOAT parts and for half parts of files before version 6,
  // which stored values unscaled.
  HalfSliceLayout layout_4d;
  std::vector<int> slice_exponents;
};

class Reader {
 public:
  Reader(Imf::IStream& stream, const std::string& source) : source_(source), file_(stream) {}

  [[noreturn]] void fail(const std::string& what) const { throwBadInput(fmt::format("{}: {}", source_, what)); }

  int findPartOrMinusOne(const char* name) const {
    for (int i = 0; i < file_.parts(); ++i) {
      if (file_.header(i).hasName() && file_.header(i).name() == name) return i;
    }
    return -1;
  }
  int findPart(const char* name) const {
    const int index = findPartOrMinusOne(name);
    if (index < 0) fail(fmt::format("part '{}' is missing", name));
    return index;
  }
  const Imf::Header& header(int part) const { return file_.header(part); }
  // The precision the bake was stored at: its single-scattering part's
  // channel type (the 2D parts are always FLOAT, and before version 6 the
  // density part was too).
  StoragePrecision storedPrecision() const {
    const Imf::ChannelList& channels = file_.header(findPart(kPartSingleRayleigh)).channels();
    return channels.begin() != channels.end() && channels.begin().channel().type == Imf::HALF ? StoragePrecision::Half
                                                                                              : StoragePrecision::Float;
  }

  template <typename Attribute>
  const Attribute& attribute(int part, const char* name) const {
    const Attribute* a = file_.header(part).findTypedAttribute<Attribute>(name);
    if (a == nullptr) fail(fmt::format("attribute {} is missing or of the wrong type", name));
    return *a;
  }

  // Finds a part and checks its window and channels against the table size
  // the config gives it. Allocates nothing.
  PartLayout checkPart(const char* name, int width, int height, const AtmosphereParameters& a,
                       const std::string& extra_channel, const std::optional<HalfSliceLayout>& layout_4d,
                       int format_version, size_t lane_groups) const {
    PartLayout layout{name, findPart(name), width, height, 0, extra_channel, {}, {}};
    const Imf::Header& h = file_.header(layout.index);
    const Imath::Box2i window = h.dataWindow();
    const long long w = 1LL * window.max.x - window.min.x + 1;
    const long long ht = 1LL * window.max.y - window.min.y + 1;
    if (window.min.x != 0 || window.min.y != 0 || w != width || ht != height) {
      fail(fmt::format("part '{}' is {}x{} texels at ({}, {}); the config says {}x{} at (0, 0)", name, w, ht,
                       window.min.x, window.min.y, width, height));
    }
    uint64_t bytes_per_texel = 0;
    std::vector<std::string> channels = channelNames(a);
    if (!extra_channel.empty()) channels.push_back(extra_channel);
    for (const std::string& channel : channels) {
      const Imf::Channel* found = h.channels().findChannel(channel);
      if (found == nullptr) fail(fmt::format("part '{}' has no channel {}", name, channel));
      if (found->type != Imf::FLOAT && found->type != Imf::HALF) {
        fail(fmt::format("part '{}' channel {} holds integers; tables are FLOAT or HALF", name, channel));
      }
      if (found->xSampling != 1 || found->ySampling != 1) {
        fail(fmt::format("part '{}' channel {} is subsampled ({}x{}); tables have one value per texel", name, channel,
                         found->xSampling, found->ySampling));
      }
      bytes_per_texel += pixelBytes(found->type);
    }
    layout.stored_bytes = bytes_per_texel * static_cast<uint64_t>(width) * static_cast<uint64_t>(height);
    const bool half = h.channels().findChannel(channels.front())->type == Imf::HALF;
    // A file before version 6 stored half values unscaled; one on Bruneton's
    // sun axis written since (formatVersionToWrite) states its exponents.
    const bool states_exponents = h.findTypedAttribute<Imf::FloatVectorAttribute>(kAttrHalfSliceExponents) != nullptr;
    if (layout_4d && half && (states_exponents || format_version >= kFirstHalfSliceExponentsFormatVersion)) {
      layout.layout_4d = *layout_4d;
      layout.slice_exponents = sliceExponents(layout.index, name, *layout_4d, lane_groups);
    }
    return layout;
  }

  // A HALF 4D part's slice exponents, one set per lane group, each an
  // integer in the range a writer makes (half_slices.h).
  std::vector<int> sliceExponents(int part, const char* name, const HalfSliceLayout& layout, size_t lane_groups) const {
    const std::vector<float>& stated = attribute<Imf::FloatVectorAttribute>(part, kAttrHalfSliceExponents).value();
    if (stated.size() != layout.sliceCount() * lane_groups) {
      fail(
          fmt::format("part '{}' attribute {} holds {} exponents; its {} x {} (r, mu_s) slices in {} lane group(s) "
                      "need {}",
                      name, kAttrHalfSliceExponents, stated.size(), layout.r_size, layout.mu_s_size, lane_groups,
                      layout.sliceCount() * lane_groups));
    }
    std::vector<int> exponents(stated.size());
    for (size_t s = 0; s < stated.size(); ++s) {
      const float e = stated[s];
      if (!(e >= kMinHalfSliceExponent && e <= kMaxHalfSliceExponent) || e != std::floor(e)) {
        fail(fmt::format("part '{}' attribute {} holds {} at slice {}: exponents are integers in [{}, {}]", name,
                         kAttrHalfSliceExponents, e, s, kMinHalfSliceExponent, kMaxHalfSliceExponent));
      }
      exponents[s] = static_cast<int>(e);
    }
    return exponents;
  }

  // Reads a checked part into each lane group's `texels` (width * height
  // texels, the group's channels in its wavelength order, unused lanes 0):
  // one group for an ordinary bake, each of a spectral one's.
  // The extra channel, if the part has one, goes to the first lane of
  // `extra_texels` (the others 0).
  struct LaneGroupTexels {
    const AtmosphereParameters* atmosphere;
    std::vector<Spectrum>* texels;
  };
  void readPart(const PartLayout& part, const std::vector<LaneGroupTexels>& groups,
                std::vector<Spectrum>* extra_texels = nullptr) {
    Imf::FrameBuffer frame;
    for (const LaneGroupTexels& g : groups) {
      g.texels->assign(static_cast<size_t>(part.width) * part.height, Spectrum(0.0f));
      char* base = reinterpret_cast<char*>(g.texels->data());
      const std::vector<std::string> channel_names = channelNames(*g.atmosphere);
      for (size_t c = 0; c < channel_names.size(); ++c) {
        frame.insert(channel_names[c],
                     Imf::Slice(Imf::FLOAT, base + c * sizeof(float), sizeof(Spectrum), sizeof(Spectrum) * part.width));
      }
    }
    if (!part.extra_channel.empty()) {
      extra_texels->assign(groups.front().texels->size(), Spectrum(0.0f));
      frame.insert(part.extra_channel, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(extra_texels->data()),
                                                  sizeof(Spectrum), sizeof(Spectrum) * part.width));
    }
    Imf::InputPart in(file_, part.index);
    in.setFrameBuffer(frame);
    in.readPixels(0, part.height - 1);
    if (!part.slice_exponents.empty()) {
      for (size_t g = 0; g < groups.size(); ++g) scaleBySlice(part, g, *groups[g].texels);
      if (!part.extra_channel.empty()) scaleBySlice(part, 0, *extra_texels);
    }
    for (const LaneGroupTexels& g : groups)
      checkTableValues(source_, part.name, *g.texels, g.atmosphere->channelCount());
    if (!part.extra_channel.empty()) checkTableValues(source_, part.name, *extra_texels, 1);
  }

 private:
  // Restores a half part's values: each half times its slice's 2^exponent.
  static void scaleBySlice(const PartLayout& part, size_t group, std::vector<Spectrum>& texels) {
    const size_t first = group * part.layout_4d.sliceCount();
    part.layout_4d.forEachTexel([&](size_t t, size_t slice) {
      const int exponent = part.slice_exponents[first + slice];
      for (int c = 0; c < kMaxChannels; ++c) texels[t][c] = scaledByPowerOfTwo(texels[t][c], exponent);
    });
  }

  std::string source_;
  Imf::MultiPartInputFile file_;
};

// A table's shape without its texels: they are allocated only once every part
// has passed its checks.
Texture2D emptyTexture2D(int width, int height) {
  Texture2D t;
  t.width = width;
  t.height = height;
  return t;
}

Texture4D emptyTexture4D(const TextureSizes& s) {
  Texture4D t;
  t.r_size = s.scattering_r;
  t.mu_size = s.scattering_mu;
  t.mu_s_size = s.scattering_mu_s;
  t.nu_size = s.scattering_nu;
  return t;
}

// How far version 2's stated ends may lie from the whole domain's and still
// be read as them. Version 2 states the 4D tables' ends as the radii and sun
// cosines of their first and last texels, which come back from the axes' own
// coordinates through a square root or a cosine: the whole domain's top
// radius a few ulps (1e-9 m) off the atmosphere's, its ends' sun coordinate
// 1e-15 off 0 or 1. Narrowed ranges end at least metres and a fraction of a
// degree inside.
constexpr double kVersion2RadiusSnap_m = 1e-3;
constexpr double kVersion2SunCoordSnap = 1e-9;

// Version 2's domain: the atmosphere's, with the 4D tables' ends converted
// from the stated radii and cosines.
AtmosphereDomain version2Domain(const Reader& in, int part, const BakeConfig& config) {
  AtmosphereDomain d = AtmosphereDomain::fromParameters(config.atmosphere);
  d.sun_axis = sunAxisOfFormatVersion(2);
  d.irradiance_rows = irradianceRowsOfFormatVersion(2);
  const Imath::V2d r = in.attribute<Imf::V2dAttribute>(part, kAttrScatteringRRange).value();
  const Imath::V2d mu_s = in.attribute<Imf::V2dAttribute>(part, kAttrScatteringMuSRange).value();
  auto rho = [&](double radius, double whole) {
    if (std::abs(radius - d.radiusAtDistanceToHorizon(whole)) <= kVersion2RadiusSnap_m) return whole;
    return d.distanceToHorizon(std::clamp(radius, d.bottom_radius_m, d.top_radius_m));
  };
  auto coord = [&](double cosine, double whole) {
    const double x = muSUnitCoord(d, cosine);
    return std::abs(x - whole) <= kVersion2SunCoordSnap ? whole : x;
  };
  d.scattering_rho_min_m = rho(r.x, 0.0);
  d.scattering_rho_max_m = rho(r.y, d.horizonToTopDistance());
  d.scattering_mu_s_coord_min = coord(mu_s.x, 0.0);
  d.scattering_mu_s_coord_max = coord(mu_s.y, 1.0);
  d.scattering_ground_views = config.scene_ranges.views_below_horizon;
  return d;
}

// The part that every version has (its name changed in version 3), and the
// version its attributes state.
struct FirstPart {
  int index;
  int version;
};

FirstPart findFirstPart(const Reader& in) {
  for (const char* name : {kPartOpticalDepth, kPartOpticalDepthVersion2}) {
    const int index = in.findPartOrMinusOne(name);
    if (index < 0) continue;
    const int version = in.attribute<Imf::IntAttribute>(index, kAttrFormatVersion).value();
    if (version < kOldestReadBakeFormatVersion || version > kBakeFormatVersion) {
      in.fail(fmt::format("format version {} is not understood by this skybake (it reads versions {} to {})", version,
                          kOldestReadBakeFormatVersion, kBakeFormatVersion));
    }
    const char* expected = version >= 3 ? kPartOpticalDepth : kPartOpticalDepthVersion2;
    if (std::string_view(name) != expected) {
      in.fail(fmt::format("part '{}' is missing (a version {} file has it)", expected, version));
    }
    return {index, version};
  }
  in.fail(fmt::format("part '{}' is missing", kPartOpticalDepth));
}

// What a read fills in: everything, or the headers alone (every attribute and
// part checked, the tables' sizes set, no texels read).
enum class ReadTables { All, None };

BakeFile readChecked(Imf::IStream& stream, const std::string& source, uint64_t file_bytes, ReadTables read) {
  Reader in(stream, source);
  // The optical-depth part is in every version and carries every attribute
  // (the others carry all but the config and the report since version 4).
  const FirstPart first = findFirstPart(in);
  BakeFile bake;
  bake.format_version = first.version;
  bake.config_toml = in.attribute<Imf::StringAttribute>(first.index, kAttrConfig).value();
  bake.orders_computed = in.attribute<Imf::IntAttribute>(first.index, kAttrOrders).value();
  if (bake.orders_computed < 1 || bake.orders_computed > kMaxOrders) {
    in.fail(fmt::format("attribute {} = {}: must be in [1, {}]", kAttrOrders, bake.orders_computed, kMaxOrders));
  }
  bake.report_json = in.attribute<Imf::StringAttribute>(first.index, kAttrBakeReport).value();
  if (first.version >= 3) {
    bake.contents =
        readContentsAttributes(in.header(first.index), first.version, [&](const std::string& what) { in.fail(what); });
    bake.contents.precision = in.storedPrecision();
    validateContents(bake.contents, source + " [header attributes]");
  } else {
    // Version 2 states the atmosphere only in the config it carries.
    const BakeConfig config = parseConfig(bake.config_toml, source + " [" + kAttrConfig + "]");
    bake.contents = storedContents(config, version2Domain(in, first.index, config));
  }
  bake.contents.multiple_shape_weight = multipleShapeWeightOfFormatVersion(first.version);
  const char* optical_depth_part = first.version >= 3 ? kPartOpticalDepth : kPartOpticalDepthVersion2;

  const TextureSizes& s = bake.contents.sizes;
  const AtmosphereParameters& a = bake.contents.atmosphere;
  // The lane groups' tables: the bake's own, or each of a spectral bake's groups'.
  std::vector<const AtmosphereParameters*> group_atmospheres;
  std::vector<BakeTables*> group_tables;
  if (bake.contents.lane_groups.empty()) {
    group_atmospheres.push_back(&a);
    group_tables.push_back(&bake.tables);
  } else {
    bake.lane_group_tables.resize(bake.contents.lane_groups.size());
    for (size_t g = 0; g < bake.contents.lane_groups.size(); ++g) {
      group_atmospheres.push_back(&bake.contents.lane_groups[g]);
      group_tables.push_back(&bake.lane_group_tables[g]);
    }
  }
  for (BakeTables* t : group_tables) {
    t->optical_depth = emptyTexture2D(s.transmittance_mu, s.transmittance_r);
    t->irradiance = emptyTexture2D(s.irradiance_mu_s, s.irradiance_r);
    t->single_rayleigh = emptyTexture4D(s);
    t->single_mie = emptyTexture4D(s);
    t->multiple_scattering = emptyTexture4D(s);
    t->multiple_density = emptyTexture4D(bake.contents.densityTableSizes());
  }
  const BakeTables& t = *group_tables.front();
  // A table's texels in any group's tables.
  auto texelsOf = [&](auto table) {
    return [table](BakeTables& tables) -> std::vector<Spectrum>& { return (tables.*table).texels; };
  };
  struct TableTexels {
    const char* part;
    int width;
    int height;
    std::function<std::vector<Spectrum>&(BakeTables&)> texels;
    std::optional<HalfSliceLayout> layout_4d = std::nullopt;
  };
  std::vector<TableTexels> tables = {
      {optical_depth_part, t.optical_depth.width, t.optical_depth.height, texelsOf(&BakeTables::optical_depth)},
      {kPartIrradiance, t.irradiance.width, t.irradiance.height, texelsOf(&BakeTables::irradiance)},
      {kPartSingleRayleigh, t.single_rayleigh.atlasWidth(), t.single_rayleigh.atlasHeight(),
       texelsOf(&BakeTables::single_rayleigh), HalfSliceLayout::of(t.single_rayleigh)},
      {kPartSingleMie, t.single_mie.atlasWidth(), t.single_mie.atlasHeight(), texelsOf(&BakeTables::single_mie),
       HalfSliceLayout::of(t.single_mie)},
      {kPartMultipleScattering, t.multiple_scattering.atlasWidth(), t.multiple_scattering.atlasHeight(),
       texelsOf(&BakeTables::multiple_scattering), HalfSliceLayout::of(t.multiple_scattering)},
      {kPartMultipleDensity, t.multiple_density.atlasWidth(), t.multiple_density.atlasHeight(),
       texelsOf(&BakeTables::multiple_density), HalfSliceLayout::of(t.multiple_density)},
  };
  std::erase_if(tables, [&](const TableTexels& table) { return leavesOut(bake.contents, table.part); });
  // Single Mie scattering combined into single_rayleigh: its first channel
  // is read from there and the others rebuilt.
  const bool combined_mie = bake.contents.combined_single_mie;
  std::vector<PartLayout> layouts;
  uint64_t stored_bytes = 0;
  for (const TableTexels& table : tables) {
    const bool with_mie = combined_mie && std::string_view(table.part) == kPartSingleRayleigh;
    layouts.push_back(in.checkPart(table.part, table.width, table.height, a,
                                   with_mie ? combinedSingleMieChannelName(a) : std::string(), table.layout_4d,
                                   first.version, group_tables.size()));
    stored_bytes += layouts.back().stored_bytes;
  }
  // A colour bake's optical depth per wavelength: the channels of every
  // wavelength group, one group's table each.
  const std::vector<AtmosphereParameters>& wavelength_groups = bake.contents.wavelength_groups;
  std::optional<PartLayout> wavelength_layout;
  if (!wavelength_groups.empty()) {
    AtmosphereParameters every_wavelength = a;
    every_wavelength.channel_kind = ChannelKind::Spectral;
    wavelength_layout = in.checkPart(kPartWavelengthOpticalDepth, t.optical_depth.width, t.optical_depth.height,
                                     every_wavelength, std::string(), std::nullopt, first.version, 1);
    stored_bytes += wavelength_layout->stored_bytes;
    bake.wavelength_optical_depth.assign(wavelength_groups.size(),
                                         emptyTexture2D(t.optical_depth.width, t.optical_depth.height));
  }
  if (stored_bytes / kMaxExrExpansion > file_bytes) {
    in.fail(
        fmt::format("the config's table sizes need {} bytes of pixel data, more than a file of {} "
                    "bytes can hold: the header is corrupt",
                    stored_bytes, file_bytes));
  }
  if (read == ReadTables::None) return bake;
  for (size_t i = 0; i < layouts.size(); ++i) {
    std::vector<Reader::LaneGroupTexels> groups;
    for (size_t g = 0; g < group_tables.size(); ++g) {
      groups.push_back({group_atmospheres[g], &tables[i].texels(*group_tables[g])});
    }
    in.readPart(layouts[i], groups, &bake.tables.single_mie.texels);
  }
  if (wavelength_layout) {
    std::vector<Reader::LaneGroupTexels> groups;
    for (size_t g = 0; g < wavelength_groups.size(); ++g) {
      groups.push_back({&wavelength_groups[g], &bake.wavelength_optical_depth[g].texels});
    }
    in.readPart(*wavelength_layout, groups);
  }
  if (combined_mie) approximateSingleMie(a, bake.tables.single_rayleigh, bake.tables.single_mie);
  // A spectral bake's group without Mie scattering holds zeros in the part
  // its others need; an ordinary bake of its wavelengths has no such table.
  for (size_t g = 0; g < group_tables.size() && group_tables.size() > 1; ++g) {
    if (!bakeStoresSingleMie(*group_atmospheres[g])) group_tables[g]->single_mie.texels = {};
  }
  return bake;
}

// Opens the stream inside the error conversion: OpenEXR reports truncated and
// corrupt files through its own exceptions, which become Error(BadInput).
template <typename OpenStream>
BakeFile readConverted(const std::string& source, uint64_t file_bytes, OpenStream open,
                       ReadTables read = ReadTables::All) {
  try {
    auto stream = open();
    return readChecked(*stream, source, file_bytes, read);
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw Error(ErrorKind::Internal, fmt::format("{}: out of memory reading the bake file", source));
  } catch (const std::exception& e) {
    throwBadInput(fmt::format("{}: not a readable skybake bake file: {}", source, e.what()));
  }
}

}  // namespace

namespace {

BakeFile readBakeFileFrom(const std::filesystem::path& path, ReadTables read) {
  const std::string source = path.string();
  // Any size: the header's promised tables are checked against it (kMaxExrExpansion).
  const uintmax_t file_bytes = requireInputFile(path, "bake file", std::numeric_limits<uintmax_t>::max());
  return readConverted(
      source, file_bytes,
      [&] {
        checkExrHeaders(path, source);
        return std::make_unique<Imf::StdIFStream>(source.c_str());
      },
      read);
}

}  // namespace

BakeFile readBakeFile(const std::filesystem::path& path) { return readBakeFileFrom(path, ReadTables::All); }

BakeFile readBakeFileHeader(const std::filesystem::path& path) { return readBakeFileFrom(path, ReadTables::None); }

BakeFile readBakeFileFromMemory(std::span<const std::byte> bytes, const std::string& source_name) {
  return readConverted(source_name, bytes.size(), [&] {
    checkExrHeaders(bytes, source_name);
    return std::make_unique<ExrMemoryStream>(bytes, source_name.c_str());
  });
}

}  // namespace skybake
