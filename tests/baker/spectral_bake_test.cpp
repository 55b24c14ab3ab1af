// Spectral bakes (channels.store = "spectral"): the config, every lane group
// against the ordinary bake of its wavelengths (bit for bit), thread counts,
// the file's channels, and the runtime's N-channel lookups.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMultiPartInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "baker/bake/bake.h"
#include "baker/bake/bake_policy.h"
#include "baker/cli/bake_memory_estimate.h"
#include "data_formats/bake_file/bake_file_attributes.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"
#include "runtime/colour/channel_luminance.h"
#include "runtime/sky.h"
#include "small_wide_atmosphere.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

// The small Earth of small_wide_atmosphere.h on `wavelengths` (a TOML
// list): any subset of them is the same atmosphere there.
std::string configText(const std::string& wavelengths, const std::string& store, const std::string& extra = "") {
  return fmt::format("name = \"spectral_test\"\n[channels]\nwavelengths_nm = {}\n{}\n{}{}\n", wavelengths,
                     store.empty() ? "" : fmt::format("store = \"{}\"", store), kSmallWideAtmosphereToml, extra);
}

const std::string kSixWavelengths = "[400, 450, 500, 550, 600, 650]";
const std::string kFirstFour = "[400, 450, 500, 550]";
const std::string kLastTwo = "[600, 650]";

fs::path tempPath(const std::string& stem) {
  return fs::temp_directory_path() / fmt::format("skybake_spectral_{}_{}.exr", stem, getpid());
}

std::vector<char> fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Whether two bakes' tables hold the same bits, texel for texel, every lane.
void expectSameTables(const BakeTables& a, const BakeTables& b, const std::string& what) {
  std::vector<const std::vector<Spectrum>*> left, right;
  forEachTable(a, [&](const char*, const std::vector<Spectrum>& t) { left.push_back(&t); });
  forEachTable(b, [&](const char*, const std::vector<Spectrum>& t) { right.push_back(&t); });
  const char* names[] = {"optical_depth",       "single_rayleigh", "single_mie",
                         "multiple_scattering", "irradiance",      "multiple_density"};
  for (size_t i = 0; i < left.size(); ++i) {
    ASSERT_EQ(left[i]->size(), right[i]->size()) << what << ": " << names[i];
    EXPECT_EQ(std::memcmp(left[i]->data(), right[i]->data(), left[i]->size() * sizeof(Spectrum)), 0)
        << what << ": " << names[i] << " differs";
  }
}

class SpectralBakeTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    SilentProgress quiet;
    spectral_ =
        new BakeOutput(bakeAtmosphere(parseConfig(configText(kSixWavelengths, "spectral"), "s.toml"), 2, quiet));
    spectral_one_thread_ =
        new BakeOutput(bakeAtmosphere(parseConfig(configText(kSixWavelengths, "spectral"), "s.toml"), 1, quiet));
    first_four_ = new BakeOutput(bakeAtmosphere(parseConfig(configText(kFirstFour, ""), "a.toml"), 2, quiet));
    last_two_ = new BakeOutput(bakeAtmosphere(parseConfig(configText(kLastTwo, ""), "b.toml"), 2, quiet));
    path_ = new fs::path(tempPath("six"));
    writeBakeFile(*path_, spectral_->file);
  }
  static void TearDownTestSuite() {
    fs::remove(*path_);
    delete spectral_;
    delete spectral_one_thread_;
    delete first_four_;
    delete last_two_;
    delete path_;
  }
  static BakeOutput* spectral_;
  static BakeOutput* spectral_one_thread_;
  static BakeOutput* first_four_;
  static BakeOutput* last_two_;
  static fs::path* path_;
};
BakeOutput* SpectralBakeTest::spectral_ = nullptr;
BakeOutput* SpectralBakeTest::spectral_one_thread_ = nullptr;
BakeOutput* SpectralBakeTest::first_four_ = nullptr;
BakeOutput* SpectralBakeTest::last_two_ = nullptr;
fs::path* SpectralBakeTest::path_ = nullptr;

TEST(SpectralConfig, GroupsOfFourInOrderAndRoundTrips) {
  const BakeConfig c = parseConfig(configText(kSixWavelengths, "spectral"), "s.toml");
  EXPECT_TRUE(c.atmosphere.storesLaneGroups());
  EXPECT_EQ(c.atmosphere.channelCount(), 6);
  ASSERT_EQ(c.colour_groups.size(), 2u);
  EXPECT_EQ(c.colour_groups[0].wavelengths_nm, (std::vector<double>{400, 450, 500, 550}));
  EXPECT_EQ(c.colour_groups[1].wavelengths_nm, (std::vector<double>{600, 650}));
  // Each group is the ordinary config of its wavelengths.
  EXPECT_EQ(c.colour_groups[1], parseConfig(configText(kLastTwo, ""), "b.toml").atmosphere);
  const std::string toml = configToToml(c);
  EXPECT_NE(toml.find("store = \"spectral\""), std::string::npos);
  const BakeConfig back = parseConfig(toml, "stored");
  EXPECT_EQ(back.atmosphere, c.atmosphere);
  EXPECT_EQ(back.colour_groups, c.colour_groups);
}

void expectRefused(const std::string& text, const std::vector<std::string>& parts) {
  try {
    parseConfig(text, "s.toml");
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    for (const std::string& p : parts) EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
  }
}

TEST(SpectralConfig, Refusals) {
  expectRefused(configText("{ min_nm = 380, max_nm = 780, count = 65 }", "spectral"),
                {"s.toml:3", "channels.wavelengths_nm", "65 wavelengths", "spectral", "at most 64"});
  expectRefused(configText(kSixWavelengths, "spectral", "combined_single_mie = true"),
                {"bake.combined_single_mie = true", "spectral"});
  // The default store: the message says what to use instead.
  expectRefused(configText(kSixWavelengths, ""),
                {"channels.wavelengths_nm", "6 wavelengths", "at most 4", "\"spectral\"", "\"cie_xyz\""});
  expectRefused(configText(kSixWavelengths, "spectrum"), {"channels.store", "\"spectral\""});
}

TEST(SpectralConfig, EstimateCountsEveryPassTables) {
  const BakeConfig spectral = settledBakeConfig(parseConfig(configText(kSixWavelengths, "spectral"), "s.toml"));
  const BakeConfig ordinary = settledBakeConfig(parseConfig(configText(kFirstFour, ""), "a.toml"));
  const BakeMemoryEstimate s = estimateBakeMemory(spectral), o = estimateBakeMemory(ordinary);
  EXPECT_EQ(s.kept_bytes, 2 * o.kept_bytes);
  EXPECT_EQ(s.peak_bytes, o.peak_bytes + o.kept_bytes);
  // Time: one order loop per pass, as a colour bake of the same wavelengths.
  const BakeConfig colour = settledBakeConfig(parseConfig(configText(kSixWavelengths, "cie_xyz"), "c.toml"));
  EXPECT_DOUBLE_EQ(estimateBakeCoreSeconds(spectral), estimateBakeCoreSeconds(colour));
}

TEST_F(SpectralBakeTest, GroupsInMemoryAreTheOrdinaryBakesOfTheirWavelengths) {
  ASSERT_EQ(spectral_->file.lane_group_tables.size(), 2u);
  expectSameTables(spectral_->file.lane_group_tables[0], first_four_->file.tables, "group 0");
  expectSameTables(spectral_->file.lane_group_tables[1], last_two_->file.tables, "group 1");
  EXPECT_EQ(spectral_->file.orders_computed, 3);
  EXPECT_EQ(spectral_->report.passes, 2);
  ASSERT_EQ(spectral_->report.wavelength_orders.size(), 3u);
  EXPECT_EQ(spectral_->report.wavelength_orders[0].mean_radiance.size(), 6u);
  EXPECT_EQ(spectral_->report.wavelength_orders[1].mean_radiance[4], last_two_->report.orders[1].mean_radiance[0]);
}

// Read back, a group is what the ordinary bake of its wavelengths reads back
// as: same contents, same tables, bit for bit (float storage is lossless).
TEST_F(SpectralBakeTest, GroupsReadBackAreTheOrdinaryBakesReadBack) {
  BakeFile read = readBakeFile(*path_);
  ASSERT_EQ(read.contents.lane_groups.size(), 2u);
  EXPECT_TRUE(read.contents.atmosphere.storesLaneGroups());
  EXPECT_EQ(read.contents.atmosphere.wavelengths_nm, (std::vector<double>{400, 450, 500, 550, 600, 650}));
  EXPECT_EQ(read.contents, spectral_->file.contents);
  const std::vector<const BakeOutput*> ordinary = {first_four_, last_two_};
  for (size_t g = 0; g < 2; ++g) {
    const fs::path path = tempPath(fmt::format("group{}", g));
    writeBakeFile(path, ordinary[g]->file);
    const BakeFile expected = readBakeFile(path);
    fs::remove(path);
    const BakeFile group = takeLaneGroup(read, g);
    EXPECT_EQ(group.contents, expected.contents) << "group " << g;
    expectSameTables(group.tables, expected.tables, fmt::format("group {} read back", g));
  }
}

TEST_F(SpectralBakeTest, FileHasOneChannelPerWavelengthAtTheCurrentFormatVersion) {
  Imf::MultiPartInputFile file(path_->c_str());
  ASSERT_GE(file.parts(), 5);
  for (int p = 0; p < file.parts(); ++p) {
    const Imf::Header& h = file.header(p);
    int channels = 0;
    for (auto it = h.channels().begin(); it != h.channels().end(); ++it) ++channels;
    EXPECT_EQ(channels, 6) << h.name();
    EXPECT_NE(h.channels().findChannel("650nm"), nullptr) << h.name();
    EXPECT_EQ(h.typedAttribute<Imf::IntAttribute>(bake_file::kAttrFormatVersion).value(), kBakeFormatVersion);
    EXPECT_EQ(h.typedAttribute<Imf::StringAttribute>(bake_file::kAttrChannels).value(), "wavelengths");
    EXPECT_EQ(h.typedAttribute<Imf::StringAttribute>(bake_file::kAttrWavelengths).value(), "400 450 500 550 600 650");
  }
}

TEST_F(SpectralBakeTest, SameTablesAndBytesForOneAndTwoThreads) {
  ASSERT_EQ(spectral_one_thread_->file.lane_group_tables.size(), 2u);
  for (size_t g = 0; g < 2; ++g) {
    expectSameTables(spectral_->file.lane_group_tables[g], spectral_one_thread_->file.lane_group_tables[g],
                     fmt::format("group {}", g));
  }
  BakeOutput a = *spectral_, b = *spectral_one_thread_;
  setStoredReport(a, false);
  setStoredReport(b, false);
  const fs::path pa = tempPath("threads2"), pb = tempPath("threads1");
  writeBakeFile(pa, a.file);
  writeBakeFile(pb, b.file);
  EXPECT_EQ(fileBytes(pa), fileBytes(pb));
  fs::remove(pa);
  fs::remove(pb);
}

TEST_F(SpectralBakeTest, ChannelLookupsAreTheGroupsLookups) {
  const Sky sky = Sky::load(*path_);
  ASSERT_EQ(sky.channelCount(), 6);
  ASSERT_EQ(sky.laneGroupCount(), 2);
  EXPECT_EQ(sky.channels().names.size(), 6u);
  EXPECT_EQ(sky.channels().kind, ChannelKind::Wavelengths);
  const Sky four(first_four_->file), two(last_two_->file);
  EXPECT_EQ(sky.laneGroup(0).channelCount(), 4);
  EXPECT_EQ(sky.laneGroup(1).channelCount(), 2);
  const double bottom = sky.atmosphere().bottom_radius_m;
  const glm::dvec3 camera(0.0, 0.0, bottom + 100.0);
  const glm::dvec3 point(3000.0, 0.0, bottom + 800.0);
  for (double sun_zenith_deg : {30.0, 85.0, 95.0}) {
    const double sz = radiansFromDegrees(sun_zenith_deg);
    const glm::dvec3 sun(std::sin(sz), 0.0, std::cos(sz));
    for (double view_zenith_deg : {0.0, 60.0, 89.0, 120.0}) {
      const double vz = radiansFromDegrees(view_zenith_deg);
      const glm::dvec3 view = glm::normalize(glm::dvec3(std::sin(vz) * 0.6, std::sin(vz) * 0.8, std::cos(vz)));
      const ChannelRadianceAndTransmittance all =
          sky.everyChannel([&](const Sky& g) { return g.skyRadiance(camera, view, sun); });
      const ChannelRadianceAndTransmittance received =
          sky.everyChannel([&](const Sky& g) { return g.receivedRadiance(camera, view, sun); });
      ASSERT_EQ(all.radiance.size(), 6u);
      // The same code on the same tables: equal exactly, and equal to the
      // ordinary bakes' lookups.
      const RadianceAndTransmittance a = four.skyRadiance(camera, view, sun), b = two.skyRadiance(camera, view, sun);
      const RadianceAndTransmittance g1 = sky.laneGroup(1).receivedRadiance(camera, view, sun);
      for (int c = 0; c < 4; ++c) {
        EXPECT_EQ(all.radiance[c], a.radiance[c]);
        EXPECT_EQ(all.transmittance[c], a.transmittance[c]);
      }
      for (int c = 0; c < 2; ++c) {
        EXPECT_EQ(all.radiance[4 + c], b.radiance[c]);
        EXPECT_EQ(received.radiance[4 + c], g1.radiance[c]);
      }
    }
    const ChannelRadianceAndTransmittance to_point =
        sky.everyChannel([&](const Sky& g) { return g.radianceToPoint(camera, point, sun); });
    const RadianceAndTransmittance b = two.radianceToPoint(camera, point, sun);
    EXPECT_EQ(to_point.radiance[5], b.radiance[1]);
    EXPECT_EQ(to_point.transmittance[4], b.transmittance[0]);
    const ChannelSunAndSkyIrradiance e =
        sky.everyChannel([&](const Sky& g) { return g.irradiance(camera, glm::dvec3(0, 0, 1), sun); });
    const SunAndSkyIrradiance ea = four.irradiance(camera, glm::dvec3(0, 0, 1), sun);
    EXPECT_EQ(e.sky[2], ea.sky[2]);
    EXPECT_EQ(e.sun[3], ea.sun[3]);
    EXPECT_EQ(sky.everyChannel([&](const Sky& g) { return g.transmittance(camera, point); })[5],
              two.transmittance(camera, point)[1]);
  }
  EXPECT_EQ(sky.everyChannel([](const Sky& g) { return g.solarRadiance(); })[4], two.solarRadiance()[0]);
  // A Spectrum holds one group: the Spectrum lookups refuse a spectral Sky.
  EXPECT_THROW(sky.skyRadiance(camera, glm::dvec3(0, 0, 1), glm::dvec3(0, 0, 1)), Error);
  EXPECT_THROW(sky.transmittance(camera, point), Error);
}

// Luminance of all six channels uses the ybar weights of the six wavelengths
// together (the piecewise-linear spectrum through all of them), not each
// group's own.
TEST_F(SpectralBakeTest, LuminanceWeighsAllWavelengths) {
  const Sky sky = Sky::load(*path_);
  const std::vector<float> expected = colour::wavelengthLuminanceWeights({400, 450, 500, 550, 600, 650});
  EXPECT_EQ(sky.channelLuminanceWeights(), expected);
  const std::vector<float> flat(6, 1.0f);
  double sum = 0.0;
  for (float w : expected) sum += w;
  EXPECT_DOUBLE_EQ(sky.luminance(flat), sum);
  EXPECT_THROW(sky.luminance(std::vector<float>(4, 1.0f)), Error);
  // An ordinary bake's channel weights are its lanes'.
  const Sky four(first_four_->file);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(four.channelLuminanceWeights()[c], four.luminanceWeights()[c]);
}

}  // namespace
}  // namespace skybake
