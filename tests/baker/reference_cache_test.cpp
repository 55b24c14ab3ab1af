// The reference cache shared by concurrent jobs: chunks written by several
// writers all count, merging loses nothing, pieces of a query set give the
// values of the whole set.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "baker/validation/reference_cache.h"
#include "baker/validation/validation.h"
#include "data_formats/angles.h"
#include "data_formats/config/config.h"

namespace skybake {
namespace {

class ReferenceCacheTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        std::filesystem::temp_directory_path() / ("skybake_reference_cache_test_" + std::to_string(::getpid()) + "_" +
                                                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  static CachedReference valueOf(double v) { return {SpectrumD(v), SpectrumD(v / 100.0), SpectrumD(0.5)}; }
  size_t chunkFiles(const ReferenceCache& cache) const {
    size_t n = 0;
    for (const auto& entry : std::filesystem::directory_iterator(cache.directory())) n += entry.is_regular_file();
    return n;
  }

  std::filesystem::path dir_;
  AtmosphereParameters atmosphere_ = builtinEarthConfig().atmosphere;
};

// The built-in Earth's cache directory keeps its name when a table-size or
// sun-domain default changes (the key pins them): a new default must not
// throw away every reference computed before it. The name is the one the
// built-in Earth's references have had since the key pinned them.
TEST_F(ReferenceCacheTest, BuiltinEarthKeyOutlivesChangesOfTheDefaults) {
  const ReferenceCache cache(dir_, atmosphere_, 32768);
  EXPECT_EQ(cache.directory().filename().string(), "reference-be39150a22785cbe");
}

// Two jobs open the cache before either has saved (as a sweep's validate
// jobs or a cluster's reference pieces do) and each adds its own queries:
// neither overwrites the other.
TEST_F(ReferenceCacheTest, ConcurrentWritersKeepEachOthersEntries) {
  ReferenceCache first(dir_, atmosphere_, 64), second(dir_, atmosphere_, 64);
  first.store("a", valueOf(1.0));
  second.store("b", valueOf(2.0));
  first.saveChunk();
  second.saveChunk();
  const ReferenceCache later(dir_, atmosphere_, 64);
  ASSERT_TRUE(later.find("a").has_value());
  ASSERT_TRUE(later.find("b").has_value());
  EXPECT_EQ(later.find("a")->value.x, 1.0);
  EXPECT_EQ(later.find("b")->value.x, 2.0);
  // Another sample count is another reference.
  EXPECT_FALSE(ReferenceCache(dir_, atmosphere_, 65).find("a").has_value());
}

// A run killed after a checkpoint keeps what the checkpoint saved.
TEST_F(ReferenceCacheTest, SavedChunksSurviveTheWriter) {
  {
    ReferenceCache killed(dir_, atmosphere_, 64);
    killed.store("saved", valueOf(3.0));
    killed.saveChunk();
    killed.store("lost", valueOf(4.0));  // never saved: the process dies here
  }
  const ReferenceCache next(dir_, atmosphere_, 64);
  EXPECT_TRUE(next.find("saved").has_value());
  EXPECT_FALSE(next.find("lost").has_value());
}

// Past kReferenceChunksBeforeMerge chunk files a reader merges them into one
// and every entry is still there.
TEST_F(ReferenceCacheTest, MergingManyChunksKeepsEveryEntry) {
  const size_t chunks = kReferenceChunksBeforeMerge + 8;
  // All opened before any writes, as by concurrent jobs: none merges.
  std::vector<ReferenceCache> writers;
  for (size_t i = 0; i < chunks; ++i) writers.emplace_back(dir_, atmosphere_, 64);
  for (size_t i = 0; i < chunks; ++i) {
    writers[i].store(fmt::format("q{}", i), valueOf(double(i)));
    writers[i].saveChunk();
  }
  EXPECT_EQ(chunkFiles(writers[0]), chunks);
  const ReferenceCache merging(dir_, atmosphere_, 64);
  EXPECT_EQ(merging.size(), chunks);
  EXPECT_EQ(chunkFiles(merging), 1u);
  const ReferenceCache after(dir_, atmosphere_, 64);
  ASSERT_EQ(after.size(), chunks);
  for (size_t i = 0; i < chunks; ++i) {
    ASSERT_TRUE(after.find(fmt::format("q{}", i)).has_value()) << i;
    EXPECT_EQ(after.find(fmt::format("q{}", i))->value.x, double(i));
  }
}

// A cache written as one file beside the directory is read too; a truncated
// chunk is ignored (its queries are recomputed), not an error.
TEST_F(ReferenceCacheTest, SingleFileCacheIsReadAndBrokenChunksIgnored) {
  const ReferenceCache probe(dir_, atmosphere_, 64);
  std::filesystem::create_directories(probe.directory());
  std::ofstream(probe.directory().string() + ".json")
      << R"({"entries": {"old": {"value": [1,2,3,4], "standard_error": [0,0,0,0], "transmittance": [1,1,1,1]}}})";
  std::ofstream(probe.directory() / "broken.json") << R"({"entries": {"x": {"value": [1,)";
  const ReferenceCache cache(dir_, atmosphere_, 64);
  ASSERT_TRUE(cache.find("old").has_value());
  EXPECT_EQ(cache.find("old")->value.y, 2.0);
  EXPECT_EQ(cache.size(), 1u);
}

// Values a reference never gives (negative or non-finite radiance or
// error, transmittance outside [0, 1]) are discarded with a note naming the
// chunk, so that their queries are recomputed instead of trusted; a
// directory named like a chunk is skipped with a note, not an error.
TEST_F(ReferenceCacheTest, ValuesOutsideThePhysicalRangeAndNonFilesAreSkippedWithANote) {
  const ReferenceCache probe(dir_, atmosphere_, 64);
  std::filesystem::create_directories(probe.directory() / "directory.json");
  const std::filesystem::path chunk = probe.directory() / "edited.json";
  std::ofstream(chunk)
      << R"({"entries": {)"
         R"("good": {"value": [1,2,3,0], "standard_error": [0,0,0,0], "transmittance": [1,1,1,1]},)"
         R"("negative": {"value": [-5,2,3,0], "standard_error": [0,0,0,0], "transmittance": [1,1,1,1]},)"
         R"("opaque": {"value": [1,2,3,0], "standard_error": [0,0,0,0], "transmittance": [1,2,1,1]},)"
         R"("noisy": {"value": [1,2,3,0], "standard_error": [0,-1,0,0], "transmittance": [1,1,1,1]}}})";
  const ReferenceCache cache(dir_, atmosphere_, 64);
  EXPECT_TRUE(cache.find("good").has_value());
  EXPECT_FALSE(cache.find("negative").has_value());
  EXPECT_FALSE(cache.find("opaque").has_value());
  EXPECT_FALSE(cache.find("noisy").has_value());
  ASSERT_EQ(cache.notes().size(), 2u);
  EXPECT_EQ(cache.notes()[0].find((probe.directory() / "directory.json").string() + ": not a regular file"), 0u)
      << cache.notes()[0];
  EXPECT_EQ(cache.notes()[1],
            chunk.string() + ": 3 value(s) outside the reference's physical range discarded; recomputed");
}

// A cache that cannot be written keeps its results in memory, with a note
// naming why, and the work goes on (validate reports from a read-only cache).
TEST_F(ReferenceCacheTest, AnUnwritableCacheKeepsResultsInMemoryWithANote) {
  std::filesystem::create_directories(dir_);
  std::ofstream(dir_ / "file") << "not a directory";
  ReferenceCache cache(dir_ / "file", atmosphere_, 64);  // its directory cannot be made under a file
  cache.store("q", valueOf(3.0));
  EXPECT_NO_THROW(cache.saveChunkIfWritable());
  ASSERT_TRUE(cache.find("q").has_value());
  EXPECT_EQ(cache.find("q")->value.x, 3.0);
  ASSERT_EQ(cache.notes().size(), 1u);
  EXPECT_NE(cache.notes()[0].find("the reference cache cannot be written"), std::string::npos) << cache.notes()[0];
  EXPECT_NE(cache.notes()[0].find(cache.directory().string()), std::string::npos) << cache.notes()[0];
}

// The pieces of a query set partition it.
TEST(ReferencePieces, PiecesPartitionTheSet) {
  const QuerySet set = querySetNamed("quick", 6360e3, 6460e3);
  for (int pieces : {1, 2, 3, 7}) {
    size_t radiance = 0, irradiance = 0;
    for (int k = 1; k <= pieces; ++k) {
      const QuerySet piece = queryPiece(set, k, pieces);
      radiance += piece.radiance.size();
      irradiance += piece.irradiance.size();
    }
    EXPECT_EQ(radiance, set.radiance.size()) << pieces;
    EXPECT_EQ(irradiance, set.irradiance.size()) << pieces;
  }
  const QuerySet first = queryPiece(set, 1, 2), second = queryPiece(set, 2, 2);
  for (const RadianceQuery& a : first.radiance) {
    for (const RadianceQuery& b : second.radiance) EXPECT_NE(radianceKey(a), radianceKey(b));
  }
}

// The reference computed in two pieces, each by its own call sharing the
// cache, is bit for bit the reference computed whole without a cache: each
// query's paths are seeded by the query, not by the run.
TEST_F(ReferenceCacheTest, PiecesGiveTheWholeSetsValues) {
  const QuerySet set = querySetNamed("quick", atmosphere_.bottom_radius_m, atmosphere_.top_radius_m);
  SilentProgress progress;
  ReferenceSettings cached{64, dir_};
  for (int k : {1, 2}) {
    const ReferenceValues piece = computeReferenceValues(atmosphere_, queryPiece(set, k, 2), cached, progress);
    EXPECT_EQ(piece.cached, 0);
  }
  const ReferenceValues from_pieces = computeReferenceValues(atmosphere_, set, cached, progress);
  EXPECT_EQ(from_pieces.computed, 0);
  EXPECT_EQ(from_pieces.cached, int(set.radiance.size() + set.irradiance.size()));
  const ReferenceValues whole = computeReferenceValues(atmosphere_, set, ReferenceSettings{64, {}}, progress);
  for (size_t i = 0; i < set.radiance.size(); ++i) {
    for (int c = 0; c < atmosphere_.channelCount(); ++c) {
      EXPECT_EQ(from_pieces.radiance[i].value[c], whole.radiance[i].value[c]) << radianceKey(set.radiance[i]);
      EXPECT_EQ(from_pieces.radiance[i].standard_error[c], whole.radiance[i].standard_error[c]);
    }
  }
  for (size_t i = 0; i < set.irradiance.size(); ++i) {
    EXPECT_EQ(from_pieces.irradiance[i].value.x, whole.irradiance[i].value.x);
  }
}

// The sun bands follow the almanac's twilights (sun depression 0-6, 6-12,
// 12-18 deg), each holding its upper zenith end.
TEST(SunBands, CivilNauticalAndAstronomicalTwilightBoundaries) {
  EXPECT_EQ(sunBand(79.99), SunBand::Day);
  EXPECT_EQ(sunBand(90.0), SunBand::LowSun);
  EXPECT_EQ(sunBand(90.01), SunBand::Twilight);
  EXPECT_EQ(sunBand(96.0), SunBand::Twilight);
  EXPECT_EQ(sunBand(96.01), SunBand::Nautical);
  EXPECT_EQ(sunBand(102.0), SunBand::Nautical);
  EXPECT_EQ(sunBand(102.01), SunBand::Astronomical);
  EXPECT_EQ(sunBand(108.0), SunBand::Astronomical);
  EXPECT_EQ(sunBand(108.01), SunBand::Night);
  EXPECT_STREQ(sunBandName(SunBand::Nautical), "nautical");
  EXPECT_STREQ(sunBandName(SunBand::Astronomical), "astronomical");
  EXPECT_EQ(allSunBands().size(), 6u);
}

// Every twilight band of the standard set has suns enough for an RMS figure:
// at least two suns (420 radiance queries) each, and the daylight queries
// are the ones they were (their cached references stay valid).
TEST(SunBands, StandardSetCoversEveryTwilightBandAndKeepsDaylightKeys) {
  const QuerySet set = standardQuerySet(6360e3, 6420e3);
  std::map<SunBand, size_t> per_band;
  for (const RadianceQuery& q : set.radiance) ++per_band[sunBand(q.sun_zenith_deg)];
  for (SunBand band : {SunBand::Twilight, SunBand::Nautical, SunBand::Astronomical}) {
    EXPECT_GE(per_band[band], 420u) << sunBandName(band);
  }
  EXPECT_EQ(per_band[SunBand::Day] + per_band[SunBand::LowSun], 1470u);  // 7 suns x 210, as before
  // Daylight keys are as they were; keys with the sun below the horizon name
  // the sampling toward sunlit air, so no value of the older sampling is used.
  EXPECT_EQ(radianceKey({0.0, 30.0, 60.0, 90.0, 0.0}), "r 0 30 60 90 0");
  EXPECT_EQ(radianceKey({0.0, 90.0, 60.0, 90.0, 0.0}), "r 0 90 60 90 0");
  EXPECT_EQ(irradianceKey({1000.0, 88.0}), "e 1000 88");
  EXPECT_EQ(radianceKey({0.0, 100.0, 60.0, 90.0, 0.0}), "r 0 100 60 90 0 guided2");
  EXPECT_EQ(irradianceKey({1000.0, 92.0}), "e 1000 92 guided2");
}

// The sky irradiance where its table is weakest: inside the aerosol layer
// and toward the top at every sun, and across every altitude's own sunset.
TEST(StandardSet, AsksForSkyIrradianceWhereItsTableIsWeakest) {
  const double bottom_m = 6360e3;
  const QuerySet set = standardQuerySet(bottom_m, bottom_m + 60e3);
  std::map<double, std::vector<double>> suns_at;
  for (const IrradianceQuery& q : set.irradiance) suns_at[q.altitude_m].push_back(q.sun_zenith_deg);
  // The 5 cameras inside the atmosphere and 2, 44 and 54 km; 15 suns each
  // and 3 around the altitude's own sunset.
  ASSERT_EQ(suns_at.size(), 8u);
  for (double altitude : {0.0, 1000.0, 2000.0, 10000.0, 30000.0, 44000.0, 54000.0, 59900.0}) {
    ASSERT_EQ(suns_at.count(altitude), 1u) << altitude;
    EXPECT_EQ(suns_at[altitude].size(), 18u) << altitude;
  }
  // 30 km up the sun sets 5.56 deg below the ground's horizon.
  const std::vector<double>& at_30_km = suns_at[30000.0];
  const double sunset_deg = 90.0 + std::acos(bottom_m / (bottom_m + 30e3)) * 180.0 / kPi;
  EXPECT_NEAR(sunset_deg, 95.56, 0.01);
  EXPECT_NE(std::find_if(at_30_km.begin(), at_30_km.end(),
                         [&](double sun) { return std::abs(sun - (sunset_deg + 0.25)) < 1e-9; }),
            at_30_km.end());
  // The radiance queries are the ones they were.
  EXPECT_EQ(set.radiance.size(), 3150u);
}

// Rays to a point with the sun below the camera's horizon take more paths
// than the set's, and their keys say so; every other query takes the set's.
TEST(ReferencePaths, TwilightRaysToPointsTakeMorePathsAndNameThemInTheirKeys) {
  const RadianceQuery twilight_point{0.0, 95.0, 80.0, 90.0, 10000.0};
  EXPECT_EQ(referencePathsFor(twilight_point, 32768), 32768 * kTwilightPointRayPathFactor);
  EXPECT_EQ(radianceKey(twilight_point),
            fmt::format("r 0 95 80 90 10000 guided2 paths x{}", kTwilightPointRayPathFactor));
  const RadianceQuery day_point{0.0, 60.0, 80.0, 90.0, 10000.0};
  EXPECT_EQ(referencePathsFor(day_point, 32768), 32768);
  EXPECT_EQ(radianceKey(day_point), "r 0 60 80 90 10000");
  const RadianceQuery twilight_sky{0.0, 95.0, 80.0, 90.0, 0.0};
  EXPECT_EQ(referencePathsFor(twilight_sky, 32768), 32768);
  EXPECT_EQ(radianceKey(twilight_sky), "r 0 95 80 90 0 guided2");
  const QuerySet set{"t", {twilight_sky, twilight_point}, {{1000.0, 95.0}}};
  EXPECT_EQ(referencePathsFor(set, 0, 64), 64);
  EXPECT_EQ(referencePathsFor(set, 1, 64), 64 * kTwilightPointRayPathFactor);
  EXPECT_EQ(referencePathsFor(set, 2, 64), 64);  // the irradiance query
}

}  // namespace
}  // namespace skybake
