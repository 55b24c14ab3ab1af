// Stored precision (bake.stored_fraction_bits, FORMAT.md "Stored
// precision"): a bake keeps its tables rounded to the bits its file stores,
// so the file reads back to the bit; the optical depths keep every bit; the
// rounding moves no lookup by more than it allows, and makes the file
// smaller.
#include <gtest/gtest.h>

#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

#include <glm/geometric.hpp>

#include "baker/bake/bake.h"
#include "data_formats/bake_file/half_slices.h"
#include "data_formats/bake_file/stored_float_bits.h"
#include "runtime/sky.h"
#include "test_configs.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

// Whether every value of `texels` has at most `fraction_bits` fraction bits.
bool keepsAtMost(const std::vector<Spectrum>& texels, int fraction_bits) {
  for (const Spectrum& t : texels) {
    for (int c = 0; c < kMaxChannels; ++c) {
      if (roundToFractionBits(t[c], fraction_bits) != t[c]) return false;
    }
  }
  return true;
}

fs::path tempBake(const char* name) {
  return fs::temp_directory_path() / (std::string("skybake_") + name + "_" + std::to_string(::getpid()) + ".exr");
}

// Float storage (half, the default, is below).
BakeConfig floatSmallEarth() {
  BakeConfig config = test::smallEarth(3);
  config.bake.precision = StoragePrecision::Float;
  return config;
}

TEST(StoredPrecision, TablesKeepTheStoredBitsAndTheFileReadsBackToTheBit) {
  SilentProgress silent;
  const BakeOutput bake = bakeAtmosphere(floatSmallEarth(), 0, silent);
  const BakeTables& t = bake.file.tables;
  EXPECT_EQ(bake.file.contents.stored_fraction_bits, kDefaultStoredFractionBits);
  for (const std::vector<Spectrum>* texels :
       {&t.single_rayleigh.texels, &t.single_mie.texels, &t.multiple_scattering.texels, &t.irradiance.texels,
        &t.multiple_density.texels}) {
    EXPECT_TRUE(keepsAtMost(*texels, kDefaultStoredFractionBits));
  }
  // The optical depths are exact: computed values use all 23 bits.
  EXPECT_FALSE(keepsAtMost(t.optical_depth.texels, kDefaultStoredFractionBits));

  const fs::path path = tempBake("stored_precision");
  writeBakeFile(path, bake.file);
  const BakeFile read = readBakeFile(path);
  fs::remove(path);
  EXPECT_EQ(read.contents.stored_fraction_bits, kDefaultStoredFractionBits);
  EXPECT_EQ(read.tables.single_rayleigh.texels, t.single_rayleigh.texels);
  EXPECT_EQ(read.tables.multiple_scattering.texels, t.multiple_scattering.texels);
  EXPECT_EQ(read.tables.multiple_density.texels, t.multiple_density.texels);
  EXPECT_EQ(read.tables.irradiance.texels, t.irradiance.texels);
  EXPECT_EQ(read.tables.optical_depth.texels, t.optical_depth.texels);
}

TEST(StoredPrecision, RoundingMovesLookupsByLessThanItsBoundAndShrinksTheFile) {
  SilentProgress silent;
  BakeConfig exact_config = floatSmallEarth();
  exact_config.bake.stored_fraction_bits = kFloatFractionBits;
  const BakeOutput exact = bakeAtmosphere(exact_config, 0, silent);
  const BakeOutput rounded = bakeAtmosphere(floatSmallEarth(), 0, silent);
  EXPECT_TRUE(keepsAtMost(exact.file.tables.multiple_scattering.texels, kFloatFractionBits));
  EXPECT_FALSE(keepsAtMost(exact.file.tables.multiple_scattering.texels, kDefaultStoredFractionBits));

  // Every table value moves by at most 2^-17 relative; a lookup is a sum of
  // such values with positive weights, so it moves by as much, plus the
  // lookup's own float arithmetic on different inputs (some ten operations
  // of 6e-8 each): 1e-5 in all.
  const double tolerance = std::ldexp(1.0, -(kDefaultStoredFractionBits + 1)) + 2.4e-6;
  const Sky exact_sky(exact.file), rounded_sky(rounded.file);
  const glm::dvec3 camera(0.0, 0.0, exact_sky.atmosphere().bottom_radius_m + 1000.0);
  for (double sun_zenith_deg : {0.0, 50.0, 85.0}) {
    const double s = sun_zenith_deg * M_PI / 180.0;
    const glm::dvec3 sun(std::sin(s), 0.0, std::cos(s));
    for (double view_zenith_deg : {0.0, 45.0, 89.0, 120.0}) {
      const double v = view_zenith_deg * M_PI / 180.0;
      const glm::dvec3 view(std::sin(v) * 0.6, std::sin(v) * 0.8, std::cos(v));
      const Spectrum e = exact_sky.skyRadiance(camera, view, sun).radiance;
      const Spectrum r = rounded_sky.skyRadiance(camera, view, sun).radiance;
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(r[c], e[c], tolerance * e[c]) << sun_zenith_deg << " " << view_zenith_deg << " " << c;
      }
    }
  }

  const fs::path exact_path = tempBake("stored_exact"), rounded_path = tempBake("stored_rounded");
  writeBakeFile(exact_path, exact.file);
  writeBakeFile(rounded_path, rounded.file);
  const uintmax_t exact_bytes = fs::file_size(exact_path), rounded_bytes = fs::file_size(rounded_path);
  fs::remove(exact_path);
  fs::remove(rounded_path);
  // Seven bits of noise fewer per value compress: the built-in Earth's file
  // is 8.6 % smaller, this small one's 2.5 % (its headers and optical
  // depths weigh more); 1 % is clear of ZIP's byte-level variation.
  EXPECT_LT(double(rounded_bytes), 0.99 * double(exact_bytes)) << rounded_bytes << " vs " << exact_bytes;
}

// Half storage (the default): every 4D value is a half times its (r, mu_s)
// slice's power of two (rounding it again changes nothing), and the file
// reads back to the bit.
TEST(StoredPrecision, HalfTablesAreScaledHalvesAndTheFileReadsBackToTheBit) {
  SilentProgress silent;
  const BakeOutput bake = bakeAtmosphere(test::smallEarth(3), 0, silent);
  ASSERT_EQ(bake.file.contents.precision, StoragePrecision::Half);
  const BakeTables& t = bake.file.tables;
  for (const Texture4D* table : {&t.single_rayleigh, &t.single_mie, &t.multiple_scattering, &t.multiple_density}) {
    std::vector<Spectrum> again = table->texels;
    const HalfSliceLayout layout = HalfSliceLayout::of(*table);
    roundToScaledHalf(layout, halfSliceExponents(layout, {{&table->texels, kMaxChannels}}), again, kMaxChannels);
    EXPECT_EQ(again, table->texels);
  }
  const fs::path path = tempBake("stored_half");
  writeBakeFile(path, bake.file);
  const BakeFile read = readBakeFile(path);
  fs::remove(path);
  EXPECT_EQ(read.contents.precision, StoragePrecision::Half);
  EXPECT_EQ(read.tables.single_rayleigh.texels, t.single_rayleigh.texels);
  EXPECT_EQ(read.tables.single_mie.texels, t.single_mie.texels);
  EXPECT_EQ(read.tables.multiple_scattering.texels, t.multiple_scattering.texels);
  EXPECT_EQ(read.tables.multiple_density.texels, t.multiple_density.texels);
  EXPECT_EQ(read.tables.irradiance.texels, t.irradiance.texels);
}

}  // namespace
}  // namespace skybake
