// Validation of a spectral bake lane group by lane group: each group's
// reference is the ordinary bake's of its wavelengths, cached where that
// bake's is; each wavelength's errors are that bake's; the groups' colour
// is the runtime's conversion of all their channels together.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "baker/bake/bake.h"
#include "baker/validation/colour_error.h"
#include "baker/validation/lane_group_validation.h"
#include "baker/validation/validation.h"
#include "data_formats/config/config.h"
#include "runtime/sky.h"
#include "small_wide_atmosphere.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

std::string configText(const std::string& wavelengths, const std::string& store) {
  return fmt::format("name = \"spectral_validation_test\"\n[channels]\nwavelengths_nm = {}\n{}\n{}\n", wavelengths,
                     store.empty() ? "" : fmt::format("store = \"{}\"", store), kSmallWideAtmosphereToml);
}

// Few paths: the reference is noisy, but these tests compare references and
// errors computed with the same seeds, not the bake's accuracy.
constexpr int kPaths = 64;

class SpectralValidationTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    SilentProgress quiet;
    const fs::path path = fs::temp_directory_path() / fmt::format("skybake_spectral_validation_{}.exr", getpid());
    writeBakeFile(
        path,
        bakeAtmosphere(parseConfig(configText("[400, 450, 500, 550, 600, 650]", "spectral"), "s.toml"), 2, quiet).file);
    spectral_ = new Sky(Sky::load(path));
    fs::remove(path);
    // The ordinary bakes of the two groups' wavelengths.
    groups_ = new std::vector<Sky>();
    for (const char* wavelengths : {"[400, 450, 500, 550]", "[600, 650]"}) {
      groups_->emplace_back(bakeAtmosphere(parseConfig(configText(wavelengths, ""), "g.toml"), 2, quiet).file);
    }
    queries_ = new QuerySet(
        querySetNamed("quick", spectral_->atmosphere().bottom_radius_m, spectral_->atmosphere().top_radius_m));
  }
  static void TearDownTestSuite() {
    delete spectral_;
    delete groups_;
    delete queries_;
  }
  static Sky* spectral_;
  static std::vector<Sky>* groups_;
  static QuerySet* queries_;
};
Sky* SpectralValidationTest::spectral_ = nullptr;
std::vector<Sky>* SpectralValidationTest::groups_ = nullptr;
QuerySet* SpectralValidationTest::queries_ = nullptr;

void expectSameReference(const std::vector<CachedReference>& a, const std::vector<CachedReference>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].value, b[i].value) << i;
    EXPECT_EQ(a[i].standard_error, b[i].standard_error) << i;
    EXPECT_EQ(a[i].transmittance, b[i].transmittance) << i;
  }
}

TEST_F(SpectralValidationTest, EachGroupsReferenceIsTheOrdinaryBakesOfItsWavelengths) {
  SilentProgress quiet;
  const ReferenceSettings no_cache{kPaths, {}};
  const std::vector<ReferenceValues> references = computeLaneGroupReferences(*spectral_, *queries_, no_cache, quiet);
  ASSERT_EQ(references.size(), 2u);
  for (size_t g = 0; g < 2; ++g) {
    // The same atmosphere and the same per-query seeds, and a reference that
    // depends on neither order nor threads: the same numbers, bit for bit.
    ASSERT_EQ(spectral_->laneGroup(static_cast<int>(g)).atmosphere(), (*groups_)[g].atmosphere());
    const ReferenceValues ordinary = computeReferenceValues((*groups_)[g].atmosphere(), *queries_, no_cache, quiet);
    expectSameReference(references[g].radiance, ordinary.radiance);
    expectSameReference(references[g].irradiance, ordinary.irradiance);
  }
  const ReferenceValues total = referenceTotals(references);
  EXPECT_EQ(total.computed, static_cast<int>(2 * (queries_->radiance.size() + queries_->irradiance.size())));
}

TEST_F(SpectralValidationTest, GroupsAreCachedWhereTheOrdinaryBakesAreAndFoundThereAgain) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("skybake_spectral_validation_cache_{}", getpid());
  fs::remove_all(dir);
  const ReferenceSettings cached{kPaths, dir};
  std::vector<fs::path> directories;
  for (int g = 0; g < 2; ++g) {
    const fs::path own = ReferenceCache(dir, spectral_->laneGroup(g).atmosphere(), kPaths).directory();
    EXPECT_EQ(own, ReferenceCache(dir, (*groups_)[g].atmosphere(), kPaths).directory()) << g;
    directories.push_back(own);
  }
  EXPECT_NE(directories[0], directories[1]);
  SilentProgress quiet;
  const std::vector<ReferenceValues> first = computeLaneGroupReferences(*spectral_, *queries_, cached, quiet);
  const std::vector<ReferenceValues> again = computeLaneGroupReferences(*spectral_, *queries_, cached, quiet);
  const int queries = static_cast<int>(queries_->radiance.size() + queries_->irradiance.size());
  for (int g = 0; g < 2; ++g) {
    EXPECT_EQ(first[g].computed, queries);
    EXPECT_EQ(again[g].computed, 0);
    EXPECT_EQ(again[g].cached, queries);
    expectSameReference(again[g].radiance, first[g].radiance);
  }
  fs::remove_all(dir);
}

TEST_F(SpectralValidationTest, EachWavelengthsErrorsAreTheOrdinaryBakesOfItsGroup) {
  SilentProgress quiet;
  const ReferenceSettings no_cache{kPaths, {}};
  const std::vector<ReferenceValues> references = computeLaneGroupReferences(*spectral_, *queries_, no_cache, quiet);
  const std::vector<MethodValues> bakes = evaluateLaneGroups(*spectral_, *queries_);
  const ErrorReport joined = compareLaneGroupsWithReference(*spectral_, *queries_, references, bakes, kPaths);
  EXPECT_EQ(joined.channel_names.size(), 6u);
  EXPECT_EQ(joined.wavelengths_nm, spectral_->atmosphere().wavelengths_nm);
  int compared = 0;
  for (int g = 0; g < 2; ++g) {
    const Sky& ordinary = (*groups_)[g];
    const ErrorReport own = compareWithReference(ordinary.atmosphere(), *queries_, references[g],
                                                 evaluateBake(ordinary, *queries_), kPaths);
    ASSERT_EQ(own.rows.size(), joined.rows.size());
    for (const ErrorRow& row : own.rows) {
      const ErrorRow* spectral_row = joined.find(row.quantity, row.band);
      ASSERT_NE(spectral_row, nullptr) << row.quantity << " " << row.band;
      ASSERT_EQ(spectral_row->channels.size(), 6u);
      for (size_t c = 0; c < row.channels.size(); ++c) {
        // The group's tables are the ordinary bake's bit for bit
        // (spectral_bake_test.cpp) and looked up by the same code against
        // the same reference: the same figures exactly.
        const ErrorStats& a = spectral_row->channels[spectral_->laneGroupFirstChannel(g) + c];
        const ErrorStats& b = row.channels[c];
        EXPECT_EQ(a.count, b.count);
        EXPECT_EQ(a.skipped, b.skipped);
        EXPECT_EQ(a.rms, b.rms) << row.quantity << " " << row.band << " channel " << c;
        EXPECT_EQ(a.p95, b.p95);
        EXPECT_EQ(a.mean, b.mean);
        EXPECT_EQ(a.max, b.max);
        EXPECT_EQ(a.reference_standard_error, b.reference_standard_error);
        compared += b.count;
      }
    }
    // The camera-altitude rows are joined the same way.
    ASSERT_EQ(own.altitude_rows.size(), joined.altitude_rows.size());
    for (size_t i = 0; i < own.altitude_rows.size(); ++i) {
      EXPECT_EQ(joined.altitude_rows[i].camera_altitude, own.altitude_rows[i].camera_altitude);
      for (size_t c = 0; c < own.altitude_rows[i].channels.size(); ++c) {
        const ErrorStats& a = joined.altitude_rows[i].channels[spectral_->laneGroupFirstChannel(g) + c];
        EXPECT_EQ(a.rms, own.altitude_rows[i].channels[c].rms);
        EXPECT_EQ(a.mean, own.altitude_rows[i].channels[c].mean);
      }
    }
  }
  // The figures are real comparisons: the day sky was compared at every
  // wavelength, with an error a bake of 8 x 32 x 8 x 4 texels cannot avoid.
  EXPECT_GT(compared, 0);
  const ErrorRow* day = joined.find("sky_radiance", "day");
  ASSERT_NE(day, nullptr);
  for (const ErrorStats& s : day->channels) {
    EXPECT_GT(s.count, 0);
    EXPECT_GT(s.rms, 0.0);
  }
  // The table shows the channels a group at a time.
  const std::string table = joined.table();
  EXPECT_NE(table.find("lane group 1 of 2 (400nm to 550nm)"), std::string::npos) << table;
  EXPECT_NE(table.find("lane group 2 of 2 (600nm to 650nm)"), std::string::npos) << table;
  EXPECT_NE(table.find("650nm rms/p95/max %"), std::string::npos) << table;
}

TEST_F(SpectralValidationTest, ColourIsAllGroupsChannelsThroughTheRuntimesConversion) {
  const std::vector<MethodValues> bakes = evaluateLaneGroups(*spectral_, *queries_);
  const MethodXyz xyz = bakeXyz(*spectral_, bakes);
  ASSERT_EQ(xyz.radiance.size(), queries_->radiance.size());
  int compared = 0;
  for (size_t i = 0; i < queries_->radiance.size(); ++i) {
    std::vector<float> channels;
    for (int g = 0; g < 2; ++g) {
      for (int c = 0; c < spectral_->laneGroup(g).channelCount(); ++c) channels.push_back(bakes[g].radiance[i][c]);
    }
    const double luminance = spectral_->luminance(channels);
    if (!(luminance > 0.0)) continue;
    // Sky::luminance weighs the same 6 channels by SpectralToXyz's ybar
    // weights times 683, stored as floats (relative rounding 6e-8 per
    // weight, summed over 6 channels): 1e-6 leaves room for it and would
    // catch the second group left out (600 and 650 nm carry a third of Y).
    EXPECT_NEAR(683.0 * xyz.radiance[i].y, luminance, 1e-6 * luminance) << i;
    ++compared;
  }
  EXPECT_GT(compared, 0);
}

}  // namespace
}  // namespace skybake
