// Bake files read from memory, and corrupt headers found by
// tests/fuzz/fuzz_bake_file: each is refused as bad input naming the file,
// before the reader allocates memory for sizes the file cannot back.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMultiPartOutputFile.h>
#include <OpenEXR/ImfOutputPart.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStringAttribute.h>

#include "data_formats/bake_file/bake_file.h"
#include "data_formats/bake_file/bake_file_attributes.h"
#include "data_formats/bake_file/bake_file_contents.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

// A valid bake at the smallest sizes the config allows, tables zero.
BakeFile tinyBake() {
  BakeFile bake;
  BakeConfig config = builtinEarthConfig();
  config.sizes = {2, 2, 2, 2, 2, 4, 2, 2, std::nullopt, std::nullopt};
  bake.contents = storedContents(config, AtmosphereDomain::fromParameters(config.atmosphere));
  bake.config_toml = configToToml(config);
  const TextureSizes& s = bake.contents.sizes;
  bake.orders_computed = 1;
  bake.report_json = "{}";
  BakeTables& t = bake.tables;
  t.optical_depth = Texture2D(s.transmittance_mu, s.transmittance_r);
  t.irradiance = Texture2D(s.irradiance_mu_s, s.irradiance_r);
  t.single_rayleigh = Texture4D(s.scattering_r, s.scattering_mu, s.scattering_mu_s, s.scattering_nu);
  t.single_mie = t.single_rayleigh;
  t.multiple_scattering = t.single_rayleigh;
  t.multiple_density = t.single_rayleigh;
  return bake;
}

std::vector<std::byte> fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> chars((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::byte> bytes(chars.size());
  std::memcpy(bytes.data(), chars.data(), chars.size());
  return bytes;
}

void writeBytes(const fs::path& path, const std::vector<std::byte>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// Expects readBakeFile to refuse `path` as bad input with a message naming the
// file and containing `fragment`.
void expectRefused(const fs::path& path, const std::string& fragment) {
  try {
    readBakeFile(path);
    FAIL() << "accepted " << path;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    const std::string message = e.what();
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
  }
}

// What a hostile writer can put in a file that skybake's own writer refuses
// to write.
struct RawBake {
  BakeContents contents;
  const BakeTables* tables = nullptr;  // null: headers only (no pixel data)
  Imf::PixelType channel_type = Imf::FLOAT;
  int orders = 1;
};

// Every part of `raw.contents` with the attributes a skybake writer gives
// them, and the tables' pixels when there are tables. Headers only, to the
// reader, is a small file that promises the tables its attributes describe.
void writeRawBake(const fs::path& path, const RawBake& raw) {
  const TextureSizes& s = raw.contents.sizes;
  const int atlas_width = s.scattering_nu * s.scattering_mu_s;
  const int atlas_height = s.scattering_r * s.scattering_mu;
  const BakeTables empty;
  const BakeTables& t = raw.tables != nullptr ? *raw.tables : empty;
  const struct {
    const char* name;
    int width;
    int height;
    const std::vector<Spectrum>* texels;
  } parts[] = {{bake_file::kPartOpticalDepth, s.transmittance_mu, s.transmittance_r, &t.optical_depth.texels},
               {bake_file::kPartSingleRayleigh, atlas_width, atlas_height, &t.single_rayleigh.texels},
               {bake_file::kPartSingleMie, atlas_width, atlas_height, &t.single_mie.texels},
               {bake_file::kPartMultipleScattering, atlas_width, atlas_height, &t.multiple_scattering.texels},
               {bake_file::kPartIrradiance, s.irradiance_mu_s, s.irradiance_r, &t.irradiance.texels},
               {bake_file::kPartMultipleDensity, atlas_width, s.scattering_r * raw.contents.density_view_size,
                &t.multiple_density.texels}};
  // Parts of a multi-part file share one display window.
  Imath::Box2i display_window({0, 0}, {0, 0});
  for (const auto& part : parts) display_window.extendBy(Imath::V2i(part.width - 1, part.height - 1));
  std::vector<Imf::Header> headers;
  for (const auto& part : parts) {
    Imf::Header header(display_window, Imath::Box2i({0, 0}, {part.width - 1, part.height - 1}));
    header.setName(part.name);
    header.setType(Imf::SCANLINEIMAGE);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (double wavelength : raw.contents.atmosphere.wavelengths_nm) {
      header.channels().insert(channelName(wavelength), Imf::Channel(raw.channel_type));
    }
    header.insert(bake_file::kAttrFormatVersion, Imf::IntAttribute(kBakeFormatVersion));
    insertContentsAttributes(raw.contents, header);
    header.insert(bake_file::kAttrConfig, Imf::StringAttribute("name = \"raw\"\n"));
    header.insert(bake_file::kAttrOrders, Imf::IntAttribute(raw.orders));
    header.insert(bake_file::kAttrBakeReport, Imf::StringAttribute("{}"));
    headers.push_back(header);
  }
  Imf::MultiPartOutputFile file(path.c_str(), headers.data(), static_cast<int>(headers.size()));
  if (raw.tables == nullptr) return;  // closed without pixels: OpenEXR leaves the chunk table empty
  for (size_t i = 0; i < headers.size(); ++i) {
    Imf::OutputPart out(file, static_cast<int>(i));
    Imf::FrameBuffer frame;
    char* base = const_cast<char*>(reinterpret_cast<const char*>(parts[i].texels->data()));
    for (size_t c = 0; c < raw.contents.atmosphere.wavelengths_nm.size(); ++c) {
      frame.insert(
          channelName(raw.contents.atmosphere.wavelengths_nm[c]),
          Imf::Slice(Imf::FLOAT, base + c * sizeof(float), sizeof(Spectrum), sizeof(Spectrum) * parts[i].width));
    }
    out.setFrameBuffer(frame);
    out.writePixels(parts[i].height);
  }
}

class BakeFileCorruptTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("skybake_bake_file_corrupt_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    good = dir / "good.exr";
    writeBakeFile(good, tinyBake());
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
  fs::path good;
};

TEST_F(BakeFileCorruptTest, MemoryReadEqualsFileRead) {
  const BakeFile from_file = readBakeFile(good);
  const BakeFile from_memory = readBakeFileFromMemory(fileBytes(good), "in memory");
  EXPECT_TRUE(from_memory.contents == from_file.contents);
  EXPECT_EQ(from_memory.config_toml, from_file.config_toml);
  EXPECT_EQ(from_memory.report_json, from_file.report_json);
  EXPECT_EQ(from_memory.tables.single_rayleigh.texels, from_file.tables.single_rayleigh.texels);
}

TEST_F(BakeFileCorruptTest, TruncatedMemoryIsRefusedNamingTheSource) {
  const std::vector<std::byte> bytes = fileBytes(good);
  for (size_t size : {size_t{0}, size_t{3}, bytes.size() / 2, bytes.size() - 1}) {
    try {
      readBakeFileFromMemory(std::span(bytes.data(), size), "download.exr");
      FAIL() << "accepted " << size << " of " << bytes.size() << " bytes";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::BadInput);
      EXPECT_EQ(std::string(e.what()).rfind("download.exr: ", 0), 0u) << e.what();
    }
  }
}

// Overwrites the declared size of the first attribute named `name` of type
// `type` (a little-endian int32 after "name\0type\0").
void setAttributeSize(std::vector<std::byte>& bytes, const std::string& name, const std::string& type, int32_t size) {
  const std::string field = name + '\0' + type + '\0';
  const auto* begin = reinterpret_cast<const char*>(bytes.data());
  const size_t at = std::search(begin, begin + bytes.size(), field.begin(), field.end()) - begin;
  ASSERT_LT(at, bytes.size());
  for (size_t i = 0; i < 4; ++i) {
    bytes[at + field.size() + i] = static_cast<std::byte>((static_cast<uint32_t>(size) >> (8 * i)) & 0xff);
  }
}

TEST_F(BakeFileCorruptTest, AttributeLargerThanTheFileIsRefused) {
  // OpenEXR's C++ reader sizes a string's buffer from its declared size
  // before reading it: 2 GB here, for a file of a few kB.
  std::vector<std::byte> bytes = fileBytes(good);
  setAttributeSize(bytes, bake_file::kAttrConfig, "string", 0x7ffffff0);
  const fs::path corrupt = dir / "huge_attribute.exr";
  writeBytes(corrupt, bytes);
  expectRefused(corrupt, "OpenEXR header: Attribute 'skybake:config', type 'string': Invalid size 2147483632");
}

TEST_F(BakeFileCorruptTest, ChannelListLongerThanItsDeclaredSizeIsRefused) {
  // OpenEXR's C++ reader reads a channel list to its end whatever its
  // declared size, so the attributes after it are read from the wrong place.
  std::vector<std::byte> bytes = fileBytes(good);
  setAttributeSize(bytes, "channels", "chlist", 8);
  const fs::path corrupt = dir / "short_channel_list.exr";
  writeBytes(corrupt, bytes);
  expectRefused(corrupt, "OpenEXR header: ");
}

TEST_F(BakeFileCorruptTest, TablesLargerThanTheFileCanHoldAreRefused) {
  // 8192 x 8192 texels of three floats: 805 MB of pixel data, promised by a
  // file of some kilobytes.
  BakeContents contents = tinyBake().contents;
  contents.sizes.transmittance_mu = 8192;
  contents.sizes.transmittance_r = 8192;
  const fs::path corrupt = dir / "huge_tables.exr";
  writeRawBake(corrupt, {contents});
  ASSERT_LT(fs::file_size(corrupt), 1u << 20);
  expectRefused(corrupt, "more than a file of");
}

// A hostile file for each check of the reader's physical ranges: values no
// bake writes, channel types no bake uses and an impossible order count. The
// fuzz corpus holds each as a seed (tests/fuzz/corpus/bake_file/out_of_range_*),
// so mutations start next to every check.
struct OutOfRangeCase {
  const char* seed_name;
  void (*spoil)(BakeTables& tables, RawBake& raw);
  const char* refusal;  // a fragment of the reader's message
};

const OutOfRangeCase kOutOfRangeCases[] = {
    {"out_of_range_negative_optical_depth",
     [](BakeTables& t, RawBake&) { t.optical_depth.texels[3] = Spectrum(-5.0f, 0.0f, 0.0f, 0.0f); },
     "part 'optical_depth' holds -5 at texel 3 (channel 0): negative"},
    {"out_of_range_negative_radiance", [](BakeTables& t, RawBake&) { t.single_rayleigh.texels[1][2] = -1e-3f; },
     "part 'single_rayleigh' holds -0.001 at texel 1 (channel 2): negative"},
    {"out_of_range_huge_radiance", [](BakeTables& t, RawBake&) { t.multiple_scattering.texels[0][1] = 3e38f; },
     "part 'multiple_scattering' holds 3e+38 at texel 0 (channel 1): larger than any bake writes"},
    {"out_of_range_uint_channels", [](BakeTables&, RawBake& raw) { raw.channel_type = Imf::UINT; },
     "part 'optical_depth' channel 680nm holds integers; tables are FLOAT or HALF"},
    {"out_of_range_negative_orders", [](BakeTables&, RawBake& raw) { raw.orders = -5; },
     "attribute skybake:orders = -5: must be in [1, 1000]"},
};

// Writes `c`'s hostile file to `path`: the tiny bake with radiance tables of
// one, then the case's one change.
void writeOutOfRangeCase(const fs::path& path, const OutOfRangeCase& c) {
  BakeFile bake = tinyBake();
  for (Spectrum& v : bake.tables.single_rayleigh.texels) v = Spectrum(1.0f, 1.0f, 1.0f, 0.0f);
  BakeTables tables = bake.tables;
  RawBake raw{bake.contents, &tables};
  c.spoil(tables, raw);
  // Integer channels are refused from the headers; a file of headers only
  // keeps the seed small.
  if (raw.channel_type == Imf::UINT) raw.tables = nullptr;
  writeRawBake(path, raw);
}

// Each hostile file is refused naming the part or attribute, the value and
// the reason.
TEST_F(BakeFileCorruptTest, ValuesOutsideEachTablesRangeAreRefused) {
  const fs::path path = dir / "raw.exr";
  // The raw writer's file of good tables reads: each refusal below is its one change.
  BakeFile bake = tinyBake();
  writeRawBake(path, {bake.contents, &bake.tables});
  EXPECT_NO_THROW(readBakeFile(path));
  for (const OutOfRangeCase& c : kOutOfRangeCases) {
    SCOPED_TRACE(c.seed_name);
    writeOutOfRangeCase(path, c);
    expectRefused(path, c.refusal);
  }
}

// The committed fuzz seeds are those files and are still refused for their
// reason (a seed the reader accepted, or refused earlier for another reason,
// would no longer lead the fuzzer to its check). With SKYBAKE_WRITE_FUZZ_SEEDS
// set to a directory, the test writes the seeds there first; from the
// repository root, SKYBAKE_WRITE_FUZZ_SEEDS=tests/fuzz/corpus/bake_file
// build/tests/data_formats_tests --gtest_filter='*FuzzSeeds*' remakes them.
TEST_F(BakeFileCorruptTest, OutOfRangeFuzzSeedsAreRefusedForTheirReason) {
  const fs::path corpus = fs::path(SKYBAKE_SOURCE_DIR) / "tests/fuzz/corpus/bake_file";
  if (const char* out = std::getenv("SKYBAKE_WRITE_FUZZ_SEEDS")) {
    for (const OutOfRangeCase& c : kOutOfRangeCases)
      writeOutOfRangeCase(fs::path(out) / (std::string(c.seed_name) + ".exr"), c);
  }
  for (const OutOfRangeCase& c : kOutOfRangeCases) {
    const fs::path seed = corpus / (std::string(c.seed_name) + ".exr");
    SCOPED_TRACE(seed.string());
    ASSERT_TRUE(fs::exists(seed));
    expectRefused(seed, c.refusal);
  }
}

// skybake's writer refuses to write what its reader would refuse, and the
// existing file stays.
TEST_F(BakeFileCorruptTest, TheWriterRefusesTablesOutsideTheirRange) {
  BakeFile bake = tinyBake();
  const auto before = fileBytes(good);
  bake.tables.multiple_scattering.texels[2] = Spectrum(std::numeric_limits<float>::infinity());
  try {
    writeBakeFile(good, bake);
    FAIL() << "wrote a non-finite table";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("part 'multiple_scattering' holds inf at texel 2"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(fileBytes(good), before);
}

// The density table may have fewer view texels than the radiance tables
// (format version 7): written and read back, it keeps its own size and every
// value; the writer refuses a table whose size the header would misstate.
TEST_F(BakeFileCorruptTest, TheDensityKeepsItsOwnViewSize) {
  BakeFile bake = tinyBake();
  bake.contents.density_view_size = 2;  // the tiny bake's radiance tables have 4
  const TextureSizes& s = bake.contents.sizes;
  Texture4D& density = bake.tables.multiple_density;
  density = Texture4D(s.scattering_r, 2, s.scattering_mu_s, s.scattering_nu);
  // The tiny bake has 3 channels; the fourth lane is not stored.
  for (size_t i = 0; i < density.texels.size(); ++i) {
    const float v = static_cast<float>(i + 1) * 0.25f;
    density.texels[i] = Spectrum(v, v, v, 0.0f);
  }
  const fs::path path = dir / "density_view_size.exr";
  writeBakeFile(path, bake);
  const BakeFile read = readBakeFile(path);
  EXPECT_EQ(read.contents.density_view_size, 2);
  EXPECT_EQ(read.tables.multiple_density.mu_size, 2);
  EXPECT_EQ(read.tables.multiple_scattering.mu_size, 4);
  // Quarters up to 8 are exact in half.
  EXPECT_EQ(read.tables.multiple_density.texels, density.texels);

  bake.contents.density_view_size = 4;
  try {
    writeBakeFile(path, bake);
    FAIL() << "wrote a density table of 2 view texels under a header stating 4";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Internal);
    EXPECT_NE(std::string(e.what()).find("the density table has 2 view texels, the contents state 4"),
              std::string::npos)
        << e.what();
  }
}

// A stated density view size below the 2 its linear axis needs, or above the
// radiance tables' view texels, is refused naming the attribute and value.
TEST_F(BakeFileCorruptTest, DensityViewSizeOutsideItsRangeIsRefused) {
  const fs::path path = dir / "density_view_size.exr";
  for (int size : {1, 6}) {
    SCOPED_TRACE(size);
    BakeContents contents = tinyBake().contents;
    contents.density_view_size = size;
    writeRawBake(path, {contents});
    expectRefused(path, "skybake:density_view_size = " + std::to_string(size) + ": must be in [2, 4]");
  }
}

}  // namespace
}  // namespace skybake
