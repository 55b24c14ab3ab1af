// Bake files: what is written is read back exactly; writes are atomic; bad
// files are refused with an error.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string_view>

#include <OpenEXR/ImfFloatVectorAttribute.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputPart.h>
#include <OpenEXR/ImfMultiPartInputFile.h>
#include <OpenEXR/ImfMultiPartOutputFile.h>
#include <OpenEXR/ImfOutputPart.h>
#include <OpenEXR/ImfStringAttribute.h>

#include "data_formats/bake_file/bake_file.h"
#include "data_formats/bake_file/bake_file_attributes.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

// A bake with small tables filled with distinct, non-round values.
BakeFile syntheticBake() {
  BakeFile bake;
  BakeConfig config = builtinEarthConfig();
  config.sizes = {8, 4, 6, 3, 3, 4, 5, 2, std::nullopt, std::nullopt};
  // A narrowed domain with ends no constant would give: the file must state
  // them exactly.
  AtmosphereDomain domain = AtmosphereDomain::fromParameters(config.atmosphere);
  domain.scattering_rho_min_m = 123456.789;
  domain.scattering_rho_max_m = 654321.0123;
  domain.scattering_mu_s_coord_min = 0.1234567891234;
  domain.scattering_mu_s_coord_max = 0.987654321;
  domain.scattering_ground_views = false;
  bake.contents = storedContents(config, domain);
  // Float storage, so that every value reads back exactly; the half tests
  // below ask for half.
  bake.contents.precision = StoragePrecision::Float;
  bake.config_toml = configToToml(config);
  const TextureSizes& s = bake.contents.sizes;
  bake.orders_computed = 3;
  bake.report_json = R"({"threads": 2, "note": "synthetic"})";
  BakeTables& t = bake.tables;
  t.optical_depth = Texture2D(s.transmittance_mu, s.transmittance_r);
  t.irradiance = Texture2D(s.irradiance_mu_s, s.irradiance_r);
  t.single_rayleigh = Texture4D(s.scattering_r, s.scattering_mu, s.scattering_mu_s, s.scattering_nu);
  t.single_mie = Texture4D(s.scattering_r, s.scattering_mu, s.scattering_mu_s, s.scattering_nu);
  t.multiple_scattering = Texture4D(s.scattering_r, s.scattering_mu, s.scattering_mu_s, s.scattering_nu);
  t.multiple_density = Texture4D(s.scattering_r, s.scattering_mu, s.scattering_mu_s, s.scattering_nu);
  float x = 0.1f;
  for (auto* texels : {&t.optical_depth.texels, &t.irradiance.texels, &t.single_rayleigh.texels, &t.single_mie.texels,
                       &t.multiple_scattering.texels, &t.multiple_density.texels}) {
    for (Spectrum& v : *texels) {
      v = Spectrum(x, x * 1.5f, x * 0.25f, 0.0f);
      x = x * 1.37f + 0.011f;
      if (x > 1e4f) x = 0.013f;
    }
  }
  return bake;
}

class BakeFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("skybake_bake_file_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
};

// Tables divided by version 7's multiple-scattering shape (a version 7
// file read and written again, whose irradiance rows are linear too) are
// written as version 7, so that a reader multiplies them back by the shape
// they were divided by.
TEST_F(BakeFileTest, TablesOnTheUnthinnedShapeAreWrittenAsVersion7) {
  BakeFile written = syntheticBake();
  written.contents.multiple_shape_weight = MultipleShapeWeight::ColumnShare;
  written.contents.domain.irradiance_rows = IrradianceRows::Linear;
  const fs::path path = dir / "version7.exr";
  writeBakeFile(path, written);
  const BakeFile read = readBakeFile(path);
  EXPECT_EQ(read.format_version, kFirstThinnedShapeFormatVersion - 1);
  EXPECT_TRUE(read.contents == written.contents);
}

// An irradiance table on linear rows (a version 8 file read and written
// again) is written as version 8, so that a reader places its rows there.
TEST_F(BakeFileTest, LinearIrradianceRowsAreWrittenAsVersion8) {
  BakeFile written = syntheticBake();
  written.contents.domain.irradiance_rows = IrradianceRows::Linear;
  const fs::path path = dir / "version8.exr";
  writeBakeFile(path, written);
  const BakeFile read = readBakeFile(path);
  EXPECT_EQ(read.format_version, kFirstCosineIrradianceRowsFormatVersion - 1);
  EXPECT_EQ(read.contents.domain.irradiance_rows, IrradianceRows::Linear);
  EXPECT_TRUE(read.contents == written.contents);
}

TEST_F(BakeFileTest, RoundTripPreservesDataAndEveryAttribute) {
  const BakeFile written = syntheticBake();
  const fs::path path = dir / "bake.exr";
  writeBakeFile(path, written);
  const BakeFile read = readBakeFile(path);
  EXPECT_TRUE(read.contents == written.contents);
  EXPECT_EQ(read.contents.domain, written.contents.domain);
  EXPECT_EQ(read.config_toml, written.config_toml);
  EXPECT_EQ(read.format_version, kBakeFormatVersion);
  EXPECT_EQ(read.contents.multiple_shape_weight, MultipleShapeWeight::ThinnedByScatteringDepth);
  EXPECT_EQ(read.orders_computed, written.orders_computed);
  EXPECT_EQ(read.report_json, written.report_json);
  // Float storage is lossless: compare exactly, channel by channel (the
  // unused fourth lane is not stored and reads back as 0).
  auto same = [](const std::vector<Spectrum>& a, const std::vector<Spectrum>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
      for (int c = 0; c < 3; ++c) ASSERT_EQ(a[i][c], b[i][c]) << i;
    }
  };
  same(read.tables.optical_depth.texels, written.tables.optical_depth.texels);
  same(read.tables.irradiance.texels, written.tables.irradiance.texels);
  same(read.tables.single_rayleigh.texels, written.tables.single_rayleigh.texels);
  same(read.tables.single_mie.texels, written.tables.single_mie.texels);
  same(read.tables.multiple_density.texels, written.tables.multiple_density.texels);
}

// Reading a bake parses no TOML: the config travels as provenance only, so
// a file whose carried config is not TOML at all reads exactly as before.
TEST_F(BakeFileTest, ReadingTakesNothingFromTheCarriedConfig) {
  BakeFile written = syntheticBake();
  written.config_toml = "this is [[ not TOML = at all";
  const fs::path path = dir / "provenance.exr";
  writeBakeFile(path, written);
  const BakeFile read = readBakeFile(path);
  EXPECT_TRUE(read.contents == written.contents);
  EXPECT_EQ(read.config_toml, written.config_toml);
}

TEST_F(BakeFileTest, HalfPrecisionKeepsThreeSignificantDigits) {
  BakeFile written = syntheticBake();
  written.contents.precision = StoragePrecision::Half;
  const fs::path path = dir / "half.exr";
  writeBakeFile(path, written);
  const BakeFile read = readBakeFile(path);
  EXPECT_EQ(read.contents.precision, StoragePrecision::Half);
  // half has an 11-bit significand: relative rounding error <= 2^-11 ~ 4.9e-4
  // for normal values (the synthetic values are all in half's normal range).
  for (size_t i = 0; i < read.tables.single_rayleigh.texels.size(); ++i) {
    const float a = written.tables.single_rayleigh.texels[i][0];
    EXPECT_NEAR(read.tables.single_rayleigh.texels[i][0], a, std::abs(a) * 4.9e-4f);
  }
}

// Half storage scales each (r, mu_s) slice by its own power of two: values
// far below half's normal range (6e-5; twilight densities reach 1e-12 W m^-3
// nm^-1) and far above its largest (65504) keep half's 11 significant bits,
// in every 4D part, the density included.
TEST_F(BakeFileTest, HalfPrecisionScalesEachSlice) {
  BakeFile written = syntheticBake();
  written.contents.precision = StoragePrecision::Half;
  // Slice (r, mu_s) scaled by 10^(3 (mu_s - r)): slices from 1e-21 to 1e12
  // times the synthetic values (0.01 to 1e4).
  for (Texture4D* t : {&written.tables.multiple_density, &written.tables.single_rayleigh}) {
    for (int r = 0; r < t->r_size; ++r)
      for (int mu = 0; mu < t->mu_size; ++mu)
        for (int mu_s = 0; mu_s < t->mu_s_size; ++mu_s)
          for (int nu = 0; nu < t->nu_size; ++nu) t->at(r, mu, mu_s, nu) *= std::pow(10.0f, 3.0f * (mu_s - r) - 6.0f);
  }
  const fs::path path = dir / "half_slices.exr";
  writeBakeFile(path, written);
  const BakeFile read = readBakeFile(path);
  // Within a slice the synthetic values span at most 1e6 (0.01 to 1e4), well
  // inside the 2^29 = 5e8 a slice keeps normal: every value within half's
  // rounding, 2^-11 = 4.9e-4 of itself.
  for (Texture4D BakeTables::*table : {&BakeTables::multiple_density, &BakeTables::single_rayleigh}) {
    const std::vector<Spectrum>& w = (written.tables.*table).texels;
    const std::vector<Spectrum>& r = (read.tables.*table).texels;
    ASSERT_EQ(w.size(), r.size());
    for (size_t i = 0; i < w.size(); ++i) {
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(r[i][c], w[i][c], std::abs(w[i][c]) * 4.9e-4f) << i << " " << c;
    }
  }
}

// A bake rounds its tables as its file stores them (settleStoredTables): the
// half file reads back to the bit, and rounding again changes nothing.
TEST_F(BakeFileTest, SettledHalfTablesReadBackToTheBit) {
  BakeFile written = syntheticBake();
  written.contents.precision = StoragePrecision::Half;
  for (Spectrum& v : written.tables.multiple_density.texels) v *= 1e-9f;
  settleStoredTables(written.contents, written.tables);
  BakeTables again = written.tables;
  settleStoredTables(written.contents, again);
  const fs::path path = dir / "half_settled.exr";
  writeBakeFile(path, written);
  const BakeFile read = readBakeFile(path);
  for (Texture4D BakeTables::*table : {&BakeTables::single_rayleigh, &BakeTables::single_mie,
                                       &BakeTables::multiple_scattering, &BakeTables::multiple_density}) {
    const std::vector<Spectrum>& w = (written.tables.*table).texels;
    for (size_t i = 0; i < w.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ((read.tables.*table).texels[i][c], w[i][c]) << i;
        ASSERT_EQ((again.*table).texels[i][c], w[i][c]) << i;
      }
    }
  }
}

// A copy of the half file at `from` whose single_rayleigh part states
// `exponents` for its slices (none: the attribute removed), pixels as they were.
void forgeSliceExponents(const fs::path& from, const fs::path& to, const std::optional<std::vector<float>>& exponents) {
  Imf::MultiPartInputFile in(from.c_str());
  std::vector<Imf::Header> headers;
  for (int p = 0; p < in.parts(); ++p) {
    const Imf::Header& source = in.header(p);
    if (source.name() != bake_file::kPartSingleRayleigh) {
      headers.push_back(source);
      continue;
    }
    // A new header with every attribute but the exponents (OpenEXR 3.1's
    // Header::erase leaks the attribute it removes).
    Imf::Header header(source.displayWindow(), source.dataWindow());
    for (Imf::Header::ConstIterator a = source.begin(); a != source.end(); ++a) {
      if (std::string_view(a.name()) != bake_file::kAttrHalfSliceExponents) header.insert(a.name(), a.attribute());
    }
    if (exponents) header.insert(bake_file::kAttrHalfSliceExponents, Imf::FloatVectorAttribute(*exponents));
    headers.push_back(header);
  }
  Imf::MultiPartOutputFile out(to.c_str(), headers.data(), static_cast<int>(headers.size()));
  for (int p = 0; p < in.parts(); ++p) {
    Imf::InputPart source(in, p);
    Imf::OutputPart(out, p).copyPixels(source);
  }
}

// A half file's slice exponents are checked like every other attribute: a
// forged or damaged list is refused with the part, the attribute and why.
TEST_F(BakeFileTest, HalfSliceExponentsOutsideTheirRulesAreRefused) {
  BakeFile written = syntheticBake();
  written.contents.precision = StoragePrecision::Half;
  const fs::path good = dir / "half_good.exr";
  writeBakeFile(good, written);
  const TextureSizes& s = written.contents.sizes;
  const size_t slices = static_cast<size_t>(s.scattering_r) * s.scattering_mu_s;
  const fs::path forged = dir / "half_forged.exr";
  auto refusal = [&](const std::optional<std::vector<float>>& exponents) {
    forgeSliceExponents(good, forged, exponents);
    try {
      readBakeFile(forged);
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::BadInput);
      return std::string(e.what());
    }
    return std::string("read without error");
  };
  auto expectRefusal = [&](const std::optional<std::vector<float>>& exponents, const std::string& reason) {
    const std::string message = refusal(exponents);
    EXPECT_NE(message.find(reason), std::string::npos) << message;
  };
  expectRefusal(std::nullopt, "skybake:half_slice_exponents is missing");
  expectRefusal(std::vector<float>(slices + 1, 0.0f), "need " + std::to_string(slices));
  std::vector<float> fractional(slices, 0.0f);
  fractional[2] = 1.5f;
  expectRefusal(fractional, "holds 1.5 at slice 2: exponents are integers");
  std::vector<float> huge(slices, 0.0f);
  huge[0] = 500.0f;
  expectRefusal(huge, "holds 500 at slice 0");
  EXPECT_NO_THROW(readBakeFile(good));
}

// The config and the report (kilobytes each) are stored once, in the part
// every bake has; every other part still carries the rest of the header.
TEST_F(BakeFileTest, ProvenanceIsStoredOnceInTheOpticalDepthPart) {
  const BakeFile written = syntheticBake();
  const fs::path path = dir / "provenance.exr";
  writeBakeFile(path, written);
  Imf::MultiPartInputFile file(path.c_str());
  ASSERT_EQ(file.parts(), 6);
  for (int p = 0; p < file.parts(); ++p) {
    const Imf::Header& h = file.header(p);
    const bool first = h.name() == bake_file::kPartOpticalDepth;
    EXPECT_EQ(h.findTypedAttribute<Imf::StringAttribute>(bake_file::kAttrConfig) != nullptr, first) << h.name();
    EXPECT_EQ(h.findTypedAttribute<Imf::StringAttribute>(bake_file::kAttrBakeReport) != nullptr, first) << h.name();
    EXPECT_NE(h.findTypedAttribute<Imf::StringAttribute>(bake_file::kAttrWavelengths), nullptr) << h.name();
  }
  const BakeFile read = readBakeFile(path);
  EXPECT_EQ(read.config_toml, written.config_toml);
  EXPECT_EQ(read.report_json, written.report_json);
}

TEST_F(BakeFileTest, FailedWriteLeavesExistingFileIntactAndNoTemporary) {
  const fs::path path = dir / "bake.exr";
  writeBakeFile(path, syntheticBake());
  const auto size_before = fs::file_size(path);
  BakeFile broken = syntheticBake();
  broken.tables.single_rayleigh.texels.clear();  // inconsistent: the write must fail
  EXPECT_THROW(writeBakeFile(path, broken), Error);
  EXPECT_EQ(fs::file_size(path), size_before);
  EXPECT_NO_THROW(readBakeFile(path));
  int entries = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    (void)entry;
    ++entries;
  }
  EXPECT_EQ(entries, 1) << "a temporary file was left behind";
}

TEST_F(BakeFileTest, UnwritableDestinationIsBadInput) {
  try {
    writeBakeFile(dir / "missing_subdir" / "bake.exr", syntheticBake());
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("missing_subdir"), std::string::npos);
  }
}

void expectRefused(const fs::path& path) {
  try {
    readBakeFile(path);
    FAIL() << "accepted " << path;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find(path.filename().string()), std::string::npos) << e.what();
  }
}

TEST_F(BakeFileTest, TruncatedGarbageAndMissingFilesAreRefused) {
  const fs::path good = dir / "bake.exr";
  writeBakeFile(good, syntheticBake());
  const auto size = fs::file_size(good);
  for (double fraction : {0.0, 0.1, 0.5, 0.9, 0.99}) {
    const fs::path cut = dir / ("truncated_" + std::to_string(static_cast<int>(fraction * 100)) + ".exr");
    fs::copy_file(good, cut);
    fs::resize_file(cut, static_cast<uintmax_t>(size * fraction));
    expectRefused(cut);
  }
  const fs::path garbage = dir / "garbage.exr";
  std::ofstream(garbage) << "this is not an OpenEXR file at all, just text";
  expectRefused(garbage);
  expectRefused(dir / "does_not_exist.exr");
}

}  // namespace
}  // namespace skybake
