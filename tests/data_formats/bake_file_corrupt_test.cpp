// Bake files read from memory, and corrupt headers found by
// tests/fuzz/fuzz_bake_file: each is refused as bad input naming the file,
// before the reader allocates memory for sizes the file cannot back.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMultiPartOutputFile.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStringAttribute.h>

#include "data_formats/bake_file.h"
#include "data_formats/bake_file_attributes.h"
#include "data_formats/bake_file_contents.h"
#include "data_formats/config.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

// A valid bake at the smallest sizes the config allows, tables zero.
BakeFile tinyBake() {
  BakeFile bake;
  BakeConfig config = builtinEarthConfig();
  config.sizes = {2, 2, 2, 2, 2, 4, 2, 2, std::nullopt};
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

// The headers of a bake whose attributes claim `contents.sizes`, every
// part's window matching them, and no pixel data: to the reader, a small file
// that promises huge tables.
void writeHeadersOnly(const fs::path& path, const BakeContents& contents) {
  const TextureSizes& s = contents.sizes;
  const int atlas_width = s.scattering_nu * s.scattering_mu_s;
  const int atlas_height = s.scattering_r * s.scattering_mu;
  const struct {
    const char* name;
    int width;
    int height;
  } parts[] = {{bake_file::kPartOpticalDepth, s.transmittance_mu, s.transmittance_r},
               {bake_file::kPartSingleRayleigh, atlas_width, atlas_height},
               {bake_file::kPartSingleMie, atlas_width, atlas_height},
               {bake_file::kPartMultipleScattering, atlas_width, atlas_height},
               {bake_file::kPartIrradiance, s.irradiance_mu_s, s.irradiance_r},
               {bake_file::kPartMultipleDensity, atlas_width, atlas_height}};
  // Parts of a multi-part file share one display window.
  Imath::Box2i display_window({0, 0}, {0, 0});
  for (const auto& part : parts) display_window.extendBy(Imath::V2i(part.width - 1, part.height - 1));
  std::vector<Imf::Header> headers;
  for (const auto& part : parts) {
    Imf::Header header(display_window, Imath::Box2i({0, 0}, {part.width - 1, part.height - 1}));
    header.setName(part.name);
    header.setType(Imf::SCANLINEIMAGE);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (double wavelength : contents.atmosphere.wavelengths_nm) {
      header.channels().insert(channelName(wavelength), Imf::Channel(Imf::FLOAT));
    }
    header.insert(bake_file::kAttrFormatVersion, Imf::IntAttribute(kBakeFormatVersion));
    insertContentsAttributes(contents, header);
    header.insert(bake_file::kAttrConfig, Imf::StringAttribute("name = \"headers only\"\n"));
    header.insert(bake_file::kAttrOrders, Imf::IntAttribute(1));
    header.insert(bake_file::kAttrBakeReport, Imf::StringAttribute("{}"));
    headers.push_back(header);
  }
  // Closed without pixels: OpenEXR leaves the chunk table empty.
  Imf::MultiPartOutputFile file(path.c_str(), headers.data(), static_cast<int>(headers.size()));
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
  writeHeadersOnly(corrupt, contents);
  ASSERT_LT(fs::file_size(corrupt), 1u << 20);
  expectRefused(corrupt, "more than a file of");
}

}  // namespace
}  // namespace skybake
