// Bake file writer. OpenEXR writes straight from the tables' float4 storage
// (a stride of one Spectrum per texel), converting to half on request.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>
#include <vector>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatVectorAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMultiPartOutputFile.h>
#include <OpenEXR/ImfOutputPart.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>
#include <fmt/format.h>

#include "data_formats/atomic_file.h"
#include "data_formats/bake_file/bake_file.h"
#include "data_formats/bake_file/bake_file_attributes.h"
#include "data_formats/bake_file/bake_file_contents.h"
#include "data_formats/bake_file/half_slices.h"
#include "data_formats/bake_file/table_values.h"
#include "data_formats/error.h"

namespace skybake {

std::string channelName(double wavelength_nm) {
  std::string text = fmt::format("{}", wavelength_nm);
  for (char& ch : text) {
    if (ch == '.') ch = 'p';
  }
  return text + "nm";
}

std::vector<std::string> channelNames(const AtmosphereParameters& a) {
  if (a.storesCieXyz()) return {"X", "Y", "Z"};
  std::vector<std::string> names;
  for (double wavelength : a.wavelengths_nm) names.push_back(channelName(wavelength));
  return names;
}

namespace {

using namespace bake_file;

// The lanes of a bake's tables, in channel order: the tables of an ordinary
// bake, or each lane group's of a spectral one.
struct LaneGroup {
  const AtmosphereParameters* atmosphere;  // its channels
  const BakeTables* tables;
};

std::vector<LaneGroup> laneGroupsOf(const BakeFile& bake) {
  if (bake.contents.lane_groups.empty()) return {{&bake.contents.atmosphere, &bake.tables}};
  if (bake.lane_group_tables.size() != bake.contents.lane_groups.size()) {
    throw Error(ErrorKind::Internal, "a spectral bake whose lane groups and their tables differ in number");
  }
  std::vector<LaneGroup> groups;
  for (size_t g = 0; g < bake.lane_group_tables.size(); ++g) {
    groups.push_back({&bake.contents.lane_groups[g], &bake.lane_group_tables[g]});
  }
  return groups;
}

struct PartToWrite {
  const char* name;
  const char* content;
  const char* units;
  // One per lane group; a group that lacks the table (a group without Mie
  // scattering in a spectral bake whose others have it) writes zeros.
  std::vector<const std::vector<Spectrum>*> texels;
  int width;
  int height;
  std::string size_text;
  // One more channel, from the first lane of other texels of the same size
  // (single Mie scattering combined into single_rayleigh), or none.
  std::string extra_channel = {};
  const std::vector<Spectrum>* extra_texels = nullptr;
  // A 4D table's layout; the 2D tables (optical depth, irradiance) have
  // none and are stored as FLOAT whatever bake.precision says (FORMAT.md).
  std::optional<HalfSliceLayout> layout_4d = std::nullopt;
  // Whose channels `texels` hold, one atmosphere per entry: the lane
  // groups' where empty (a colour bake's wavelength optical depths have
  // their own).
  std::vector<const AtmosphereParameters*> channel_groups = {};
};

// The channel names of a part, in channel order.
std::vector<std::string> partChannelNames(const PartToWrite& part, const std::vector<LaneGroup>& groups) {
  std::vector<std::string> names;
  auto add = [&](const AtmosphereParameters& a) {
    const std::vector<std::string> group_names = channelNames(a);
    names.insert(names.end(), group_names.begin(), group_names.end());
  };
  if (part.channel_groups.empty()) {
    for (const LaneGroup& g : groups) add(*g.atmosphere);
  } else {
    for (const AtmosphereParameters* a : part.channel_groups) add(*a);
  }
  return names;
}

bool storedAsHalf(const BakeFile& bake, const PartToWrite& part) {
  return bake.contents.precision == StoragePrecision::Half && part.layout_4d.has_value();
}

// A half part's (r, mu_s) slice exponents (half_slices.h), one set per lane
// group, each over that group's channels (and the extra channel, which only
// an ordinary bake has): every group's values are those of the ordinary bake
// of its wavelengths.
std::vector<int> sliceExponentsOf(const PartToWrite& part, const std::vector<LaneGroup>& groups) {
  std::vector<int> exponents;
  for (size_t g = 0; g < groups.size(); ++g) {
    std::vector<HalfSliceLanes> lanes = {{part.texels[g], groups[g].atmosphere->channelCount()}};
    if (part.extra_texels != nullptr) lanes.push_back({part.extra_texels, 1});
    const std::vector<int> group = halfSliceExponents(*part.layout_4d, lanes);
    exponents.insert(exponents.end(), group.begin(), group.end());
  }
  return exponents;
}

// Parts of a multi-part file must share one display window; each part's data
// window is its own table size.
Imf::Header makeHeader(const BakeFile& bake, const PartToWrite& part, const std::vector<LaneGroup>& groups,
                       const Imath::Box2i& display_window, const std::vector<int>& slice_exponents) {
  Imf::Header header(display_window, Imath::Box2i({0, 0}, {part.width - 1, part.height - 1}));
  header.setName(part.name);
  header.setType(Imf::SCANLINEIMAGE);
  header.compression() = Imf::ZIP_COMPRESSION;
  const Imf::PixelType type = storedAsHalf(bake, part) ? Imf::HALF : Imf::FLOAT;
  for (const std::string& channel : partChannelNames(part, groups)) {
    header.channels().insert(channel, Imf::Channel(type));
  }
  if (part.extra_texels != nullptr) header.channels().insert(part.extra_channel, Imf::Channel(type));
  header.insert(kAttrFormatVersion, Imf::IntAttribute(formatVersionToWrite(bake.contents)));
  header.insert(kAttrContent, Imf::StringAttribute(part.content));
  header.insert(kAttrUnits, Imf::StringAttribute(part.units));
  header.insert(kAttrTableSize, Imf::StringAttribute(part.size_text));
  if (storedAsHalf(bake, part)) {
    header.insert(kAttrHalfSliceExponents,
                  Imf::FloatVectorAttribute(std::vector<float>(slice_exponents.begin(), slice_exponents.end())));
  }
  insertContentsAttributes(bake.contents, header);
  header.insert(kAttrOrders, Imf::IntAttribute(bake.orders_computed));
  // The provenance (a few kilobytes of config and report) once, in the part
  // every bake has and every reader takes them from: repeated in each part
  // it made a colour bake's headers 50 KB.
  if (part.name == std::string_view(kPartOpticalDepth)) {
    header.insert(kAttrConfig, Imf::StringAttribute(bake.config_toml));
    header.insert(kAttrBakeReport, Imf::StringAttribute(bake.report_json));
  }
  return header;
}

void writeParts(const std::string& file_name, const BakeFile& bake, const std::vector<PartToWrite>& parts) {
  Imath::Box2i display_window({0, 0}, {0, 0});
  for (const PartToWrite& part : parts) {
    display_window.extendBy(Imath::V2i(part.width - 1, part.height - 1));
  }
  const std::vector<LaneGroup> groups = laneGroupsOf(bake);
  std::vector<std::vector<int>> slice_exponents;
  std::vector<Imf::Header> headers;
  for (const PartToWrite& part : parts) {
    slice_exponents.push_back(storedAsHalf(bake, part) ? sliceExponentsOf(part, groups) : std::vector<int>());
    headers.push_back(makeHeader(bake, part, groups, display_window, slice_exponents.back()));
  }
  Imf::MultiPartOutputFile file(file_name.c_str(), headers.data(), static_cast<int>(headers.size()));
  for (size_t i = 0; i < parts.size(); ++i) {
    const PartToWrite& part = parts[i];
    const bool half = storedAsHalf(bake, part);
    Imf::OutputPart out(file, static_cast<int>(i));
    Imf::FrameBuffer frame;
    // Half storage: each value scaled by its slice's power of two and
    // converted here, one half4 per texel, same layout as the floats.
    auto toHalves = [&](const std::vector<Spectrum>& texels, size_t group) {
      std::vector<Imath::half> halves(texels.size() * kMaxChannels);
      const size_t first = group * part.layout_4d->sliceCount();
      part.layout_4d->forEachTexel([&](size_t t, size_t slice) {
        const int exponent = slice_exponents[i][first + slice];
        for (int c = 0; c < kMaxChannels; ++c) {
          halves[t * kMaxChannels + c] = Imath::half(scaledByPowerOfTwo(texels[t][c], -exponent));
        }
      });
      return halves;
    };
    // Kept alive until the part is written: the slices point into them.
    std::vector<std::vector<Imath::half>> halves(part.texels.size() + 1);
    std::vector<Imath::half> extra_halves;
    const size_t value_bytes = half ? sizeof(Imath::half) : sizeof(float);
    const size_t texel_bytes = value_bytes * kMaxChannels;
    const Imf::PixelType type = half ? Imf::HALF : Imf::FLOAT;
    auto baseOf = [&](const std::vector<Spectrum>& texels, std::vector<Imath::half>& as_halves, size_t group) {
      if (half) as_halves = toHalves(texels, group);
      return half ? reinterpret_cast<char*>(as_halves.data())
                  : const_cast<char*>(reinterpret_cast<const char*>(texels.data()));
    };
    // Allocated only for a group that lacks the table.
    std::vector<Spectrum> zeros;
    for (size_t g = 0; g < part.texels.size(); ++g) {
      if (part.texels[g]->empty() && zeros.empty()) {
        zeros.assign(static_cast<size_t>(part.width) * part.height, Spectrum(0.0f));
      }
      const std::vector<Spectrum>& texels = part.texels[g]->empty() ? zeros : *part.texels[g];
      char* base = baseOf(texels, halves[g], g);
      const std::vector<std::string> channel_names =
          channelNames(part.channel_groups.empty() ? *groups[g].atmosphere : *part.channel_groups[g]);
      for (size_t c = 0; c < channel_names.size(); ++c) {
        frame.insert(channel_names[c], Imf::Slice(type, base + c * value_bytes, texel_bytes, texel_bytes * part.width));
      }
    }
    if (part.extra_texels != nullptr) {
      frame.insert(part.extra_channel, Imf::Slice(type, baseOf(*part.extra_texels, extra_halves, 0), texel_bytes,
                                                  texel_bytes * part.width));
    }
    out.setFrameBuffer(frame);
    out.writePixels(part.height);
  }
}

std::string table4DSizeText(const Texture4D& t) {
  return fmt::format("r={} mu={} mu_s={} nu={}", t.r_size, t.mu_size, t.mu_s_size, t.nu_size);
}

// A colour bake's optical depth per wavelength: one channel per wavelength,
// each wavelength group's table what its pass stored as optical_depth.
PartToWrite wavelengthOpticalDepthPart(const BakeFile& bake) {
  const std::vector<AtmosphereParameters>& groups = bake.contents.wavelength_groups;
  if (bake.wavelength_optical_depth.size() != groups.size()) {
    throw Error(ErrorKind::Internal, "a colour bake whose wavelength groups and their optical depths differ in number");
  }
  const Texture2D& shape = bake.tables.optical_depth;
  PartToWrite part{kPartWavelengthOpticalDepth,
                   "each wavelength's optical depth from (r, mu) to the top boundary; transmittance = exp(-value)",
                   "dimensionless",
                   {},
                   shape.width,
                   shape.height,
                   fmt::format("mu={} r={}", shape.width, shape.height)};
  for (size_t g = 0; g < groups.size(); ++g) {
    part.texels.push_back(&bake.wavelength_optical_depth[g].texels);
    part.channel_groups.push_back(&groups[g]);
  }
  return part;
}

}  // namespace

void setBakeFileWriteThreads(int threads) { Imf::setGlobalThreadCount(std::max(threads, 0)); }

void writeBakeFile(const std::filesystem::path& path, const BakeFile& bake,
                   const std::function<void(const std::filesystem::path& temp)>& before_rename) {
  const std::vector<LaneGroup> groups = laneGroupsOf(bake);
  // Sizes are the first group's: every group's tables have the same.
  const BakeTables& t = *groups.front().tables;
  auto texels = [&](auto table) {
    std::vector<const std::vector<Spectrum>*> out;
    for (const LaneGroup& g : groups) out.push_back(&(g.tables->*table).texels);
    return out;
  };
  // A 4D table's part: its atlas and layout.
  auto table4D = [&](const char* name, const char* content, const char* units, Texture4D BakeTables::*table) {
    const Texture4D& shape = t.*table;
    PartToWrite part{
        name, content, units, texels(table), shape.atlasWidth(), shape.atlasHeight(), table4DSizeText(shape)};
    part.layout_4d = HalfSliceLayout::of(shape);
    return part;
  };
  std::vector<PartToWrite> parts = {
      {kPartOpticalDepth, "optical depth from (r, mu) to the top boundary; transmittance = exp(-value)",
       "dimensionless", texels(&BakeTables::optical_depth), t.optical_depth.width, t.optical_depth.height,
       fmt::format("mu={} r={}", t.optical_depth.width, t.optical_depth.height)},
      table4D(kPartSingleRayleigh, "single Rayleigh scattering radiance divided by the Rayleigh phase function",
              "W m^-2 nm^-1 (radiance W m^-2 sr^-1 nm^-1 over phase sr^-1)", &BakeTables::single_rayleigh),
      table4D(kPartSingleMie, "single Mie scattering radiance divided by the Mie phase function",
              "W m^-2 nm^-1 (radiance W m^-2 sr^-1 nm^-1 over phase sr^-1)", &BakeTables::single_mie),
      table4D(kPartMultipleScattering,
              "scattering orders 2 and up, radiance divided by the multiple-scattering shape at the texel's r and nu",
              "W m^-2 nm^-1 (radiance W m^-2 sr^-1 nm^-1 over shape sr^-1)", &BakeTables::multiple_scattering),
      {kPartIrradiance, "sky irradiance on a horizontal surface at (r, mu_s), direct sun excluded", "W m^-2 nm^-1",
       texels(&BakeTables::irradiance), t.irradiance.width, t.irradiance.height,
       fmt::format("mu_s={} r={}", t.irradiance.width, t.irradiance.height)},
      table4D(kPartMultipleDensity,
              "scattering density of orders 2 and up: light scattered per unit length toward the viewer, "
              "divided by the multiple-scattering shape at the texel's r and nu",
              "W m^-3 nm^-1 (W m^-3 sr^-1 nm^-1 over shape sr^-1)", &BakeTables::multiple_density),
  };
  if (!bake.contents.wavelength_groups.empty()) {
    parts.push_back(wavelengthOpticalDepthPart(bake));
  }
  if (bake.contents.combined_single_mie) {
    auto is_rayleigh = [](const PartToWrite& p) { return p.name == std::string_view(kPartSingleRayleigh); };
    PartToWrite& rayleigh = *std::find_if(parts.begin(), parts.end(), is_rayleigh);
    rayleigh.extra_channel = combinedSingleMieChannelName(bake.contents.atmosphere);
    rayleigh.extra_texels = &t.single_mie.texels;
  }
  std::erase_if(parts, [&](const PartToWrite& p) { return leavesOut(bake.contents, p.name); });
  // The header states the density's view size; a reader sizes the part by it.
  if (!leavesOut(bake.contents, kPartMultipleDensity) &&
      t.multiple_density.mu_size != bake.contents.density_view_size) {
    throw Error(ErrorKind::Internal,
                fmt::format("{}: the density table has {} view texels, the contents state {}", path.string(),
                            t.multiple_density.mu_size, bake.contents.density_view_size));
  }
  for (const PartToWrite& part : parts) {
    const size_t size = static_cast<size_t>(part.width) * part.height;
    // Only a spectral bake's group without Mie scattering may lack a written table.
    for (size_t g = 0; g < part.texels.size(); ++g) {
      const bool may_lack = groups.size() > 1 && part.name == std::string_view(kPartSingleMie) &&
                            !bakeStoresSingleMie(*groups[g].atmosphere);
      if ((part.texels[g]->size() != size && !(may_lack && part.texels[g]->empty())) || part.width <= 0 ||
          (part.extra_texels != nullptr && part.extra_texels->size() != size)) {
        throw Error(ErrorKind::Internal, fmt::format("{}: part {} has no data of its size", path.string(), part.name));
      }
    }
  }

  // A table outside its range (a config whose numbers overflow float) is
  // refused before anything is written: the existing file stays.
  for (const PartToWrite& part : parts) {
    for (size_t g = 0; g < part.texels.size(); ++g) {
      const AtmosphereParameters& a = part.channel_groups.empty() ? *groups[g].atmosphere : *part.channel_groups[g];
      checkTableValues(path.string(), part.name, *part.texels[g], a.channelCount());
    }
    if (part.extra_texels != nullptr) checkTableValues(path.string(), part.name, *part.extra_texels, 1);
  }

  writeFileAtomically(path, [&](const std::filesystem::path& temp) {
    writeParts(temp.string(), bake, parts);
    if (before_rename) before_rename(temp);
  });
}

}  // namespace skybake
