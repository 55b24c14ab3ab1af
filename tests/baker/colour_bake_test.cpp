// Colour bakes (channels.store = "cie_xyz"): the XYZ tables against the same
// wavelengths baked as ordinary passes of at most 4, the file and the
// runtime's view of its channels.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputPart.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMultiPartInputFile.h>
#include <OpenEXR/ImfMultiPartOutputFile.h>
#include <OpenEXR/ImfOutputPart.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "baker/bake/bake.h"
#include "baker/bake/bake_passes.h"
#include "baker/bake/bake_policy.h"
#include "baker/render/image_colour.h"
#include "data_formats/bake_file/bake_file_attributes.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"
#include "runtime/colour/colour_bake_weights.h"
#include "runtime/colour/luminance.h"
#include "runtime/colour/spectral_to_xyz.h"
#include "runtime/sky.h"
#include "small_wide_atmosphere.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

// The small Earth of small_wide_atmosphere.h on `count` wavelengths from
// 380 to 780 nm, integrated into X, Y, Z.
std::string colourConfigText(int count) {
  return fmt::format(
      "name = \"colour_test\"\n[channels]\nwavelengths_nm = {{ min_nm = 380, max_nm = 780, count = {} }}\n"
      "store = \"cie_xyz\"\n{}",
      count, kSmallWideAtmosphereToml);
}

class ColourBakeTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    config_ = new BakeConfig(parseConfig(colourConfigText(15), "colour_test.toml"));
    // Float storage: the sums below are compared within float's rounding
    // (half storage rounds each value by up to 2^-11 of its slice's scale).
    config_->bake.precision = StoragePrecision::Float;
    SilentProgress quiet;
    colour_ = new BakeOutput(bakeAtmosphere(*config_, 2, quiet));
    const BakeConfig settled = settledBakeConfig(*config_);
    passes_ = new std::vector<BakeOutput>();
    for (size_t g = 0; g < settled.colour_groups.size(); ++g) {
      // Every bit kept, as the colour bake's own passes keep them.
      BakeConfig pass = passConfig(settled, g);
      pass.bake.stored_fraction_bits = kFloatFractionBits;
      passes_->push_back(bakeAtmosphere(pass, 2, quiet));
    }
  }
  static void TearDownTestSuite() {
    delete config_;
    delete colour_;
    delete passes_;
  }
  static BakeConfig* config_;
  static BakeOutput* colour_;
  static std::vector<BakeOutput>* passes_;
};
BakeConfig* ColourBakeTest::config_ = nullptr;
BakeOutput* ColourBakeTest::colour_ = nullptr;
std::vector<BakeOutput>* ColourBakeTest::passes_ = nullptr;

// The tables whose XYZ is a plain weighted sum of the wavelengths' (their
// stored form does not depend on the channel): each channel equals the
// colour-matching-weighted sum of the passes' tables. Both sides sum 15
// float products of float weights; the bake sums them in float, 4 lanes per
// pass, the test in double: they differ by a few float roundings of the
// largest term, well below 1e-5 of the sum of the terms' magnitudes. The
// stored sum is then rounded to the stored fraction bits, at most 2^-17
// (7.6e-6) of itself (data_formats/bake_file/stored_float_bits.h).
constexpr double kLinearSumTolerance = 1e-5 + 7.6e-6;

template <typename Member>
void expectWeightedSum(const BakeOutput& colour, const std::vector<BakeOutput>& passes,
                       const colour::ColourBakeWeights& w, Member table, const char* name) {
  const std::vector<Spectrum>& xyz = (colour.file.tables.*table).texels;
  ASSERT_FALSE(xyz.empty()) << name;
  int worst_reported = 0;
  for (size_t t = 0; t < xyz.size(); ++t) {
    for (int c = 0; c < kCieXyzChannels; ++c) {
      double sum = 0.0, magnitude = 0.0;
      int i = 0;
      for (const BakeOutput& pass : passes) {
        const std::vector<Spectrum>& lanes = (pass.file.tables.*table).texels;
        for (int l = 0; l < pass.file.contents.atmosphere.channelCount(); ++l, ++i) {
          sum += w.colourMatching(c, i) * lanes[t][l];
          magnitude += std::abs(w.colourMatching(c, i) * lanes[t][l]);
        }
      }
      const double error = std::abs(xyz[t][c] - sum);
      if (!(error <= kLinearSumTolerance * magnitude + 1e-30) && worst_reported++ < 5) {
        ADD_FAILURE() << name << " texel " << t << " channel " << c << ": " << xyz[t][c] << " vs " << sum;
      }
    }
  }
}

TEST_F(ColourBakeTest, PassesAreGroupsOfAtMostFourWavelengths) {
  ASSERT_EQ(passes_->size(), 4u);
  EXPECT_EQ((*passes_)[3].file.contents.atmosphere.channelCount(), 3);
  EXPECT_EQ(colour_->file.contents.atmosphere.channelCount(), 3);
  EXPECT_EQ(colour_->file.contents.atmosphere.wavelengths_nm.size(), 15u);
}

TEST_F(ColourBakeTest, ExactTablesAreTheColourMatchingSumOfTheWavelengthPasses) {
  const colour::ColourBakeWeights w(config_->colour_groups);
  expectWeightedSum(*colour_, *passes_, w, &BakeTables::single_rayleigh, "single_rayleigh");
  expectWeightedSum(*colour_, *passes_, w, &BakeTables::single_mie, "single_mie");
  expectWeightedSum(*colour_, *passes_, w, &BakeTables::irradiance, "irradiance");
}

// The optical depth is the effective depth of sunlight: exp(-tau_c) is the
// sunlight-weighted mean transmittance of the wavelengths. Computed in
// double from float depths and stored in float: rounding tau to float moves
// exp(-tau) by tau * 6e-8 relative, under 3e-6 for the depths of at most ~50
// here; 1e-5 relative covers that and the float weights.
TEST_F(ColourBakeTest, OpticalDepthIsTheEffectiveDepthOfSunlight) {
  const colour::ColourBakeWeights w(config_->colour_groups);
  const std::vector<Spectrum>& xyz = colour_->file.tables.optical_depth.texels;
  for (size_t t = 0; t < xyz.size(); ++t) {
    for (int c = 0; c < kCieXyzChannels; ++c) {
      double transmitted = 0.0;
      int i = 0;
      for (const BakeOutput& pass : *passes_) {
        for (int l = 0; l < pass.file.contents.atmosphere.channelCount(); ++l, ++i) {
          transmitted += w.sunlightShare(c, i) * std::exp(-double(pass.file.tables.optical_depth.texels[t][l]));
        }
      }
      const double stored = std::exp(-double(xyz[t][c]));
      ASSERT_NEAR(stored, transmitted, 1e-5 * transmitted + 1e-30) << "texel " << t << " channel " << c;
      ASSERT_GE(xyz[t][c], 0.0f);
    }
  }
}

TEST_F(ColourBakeTest, EveryTableIsNonNegativeAndFinite) {
  forEachTable(colour_->file.tables, [](const char* part, const std::vector<Spectrum>& texels) {
    for (const Spectrum& s : texels) {
      for (int c = 0; c < kCieXyzChannels; ++c) {
        ASSERT_TRUE(std::isfinite(s[c]) && s[c] >= 0.0f) << part << ": " << s[c];
      }
      ASSERT_EQ(s[3], 0.0f) << part << ": the unused lane";
    }
  });
}

// Day-sky lookups: single scattering interpolates the exact tables (linear
// interpolation commutes with the weighted sum), multiple scattering differs
// only in the shape its interpolation divides by, and the sun disk's
// transmittance is the effective one, exact for the direct sun.
TEST_F(ColourBakeTest, DaySkyLuminanceMatchesTheWavelengthPasses) {
  const Sky colour(colour_->file);
  std::vector<Sky> passes;
  for (const BakeOutput& p : *passes_) passes.emplace_back(p.file);
  const colour::ColourBakeWeights w(config_->colour_groups);
  const glm::dvec3 camera(0.0, 0.0, colour.atmosphere().bottom_radius_m + 100.0);
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.6, 0.0, 0.8));
  for (double zenith_deg : {0.0, 30.0, 60.0, 80.0}) {
    for (double azimuth_deg : {0.0, 90.0, 180.0}) {
      const double z = radiansFromDegrees(zenith_deg), az = radiansFromDegrees(azimuth_deg);
      const glm::dvec3 view(std::sin(z) * std::cos(az), std::sin(z) * std::sin(az), std::cos(z));
      const RadianceAndTransmittance xyz = colour.skyRadiance(camera, view, sun);
      double y = 0.0, t_y = 0.0;
      int i = 0;
      for (const Sky& p : passes) {
        const RadianceAndTransmittance r = p.skyRadiance(camera, view, sun);
        for (int l = 0; l < p.channelCount(); ++l, ++i) {
          y += w.colourMatching(1, i) * r.radiance[l];
          t_y += w.sunlightShare(1, i) * r.transmittance[l];
        }
      }
      // The multiple-scattering shape's interpolation differs between
      // texels: a few per mille of the multiple-scattering part, itself
      // under a third of the day sky.
      EXPECT_NEAR(xyz.radiance[1], y, 2e-3 * y) << zenith_deg << " " << azimuth_deg;
      // The view ray's transmittance (not the sun's): the effective depth is
      // exact only for sunlight from the top; along a view ray it weights
      // the wavelengths by the sun at the top too, a per-mille effect here.
      EXPECT_NEAR(xyz.transmittance[1], t_y, 2e-3) << zenith_deg << " " << azimuth_deg;
      EXPECT_NEAR(colour.luminance(xyz.radiance), 683.0 * xyz.radiance[1], 1e-6 * 683.0 * xyz.radiance[1]);
    }
  }
}

// Twilight lookups integrate single scattering along the view ray; a colour
// bake does it per wavelength from each pass's own optical depths and sums
// the wavelengths into X, Y, Z at each node, so its X, Y, Z follow the
// passes' lookups summed with the colour-matching weights. From the X, Y,
// Z atmosphere's effective depths and coefficients (a product of means
// where the truth is the mean of a product) they read 3 to 20 % off here.
// What may differ: the nodes (placed by the X, Y, Z atmosphere's
// extinction, a pass's by its own, both rules converged to about 0.1 %),
// the multiple-scattering shape's interpolation (a few per mille of the
// multiple part, as by day) and float sums: 1 % of each channel, and 0.5 %
// RMS over the views.
TEST_F(ColourBakeTest, TwilightColourFollowsTheWavelengthPasses) {
  const Sky colour(colour_->file);
  ASSERT_EQ(colour.wavelengthGroupsToXyz().size(), passes_->size());
  std::vector<Sky> passes;
  for (const BakeOutput& p : *passes_) passes.emplace_back(p.file);
  const colour::ColourBakeWeights w(config_->colour_groups);
  const glm::dvec3 camera(0.0, 0.0, colour.atmosphere().bottom_radius_m + 100.0);
  double sum_squares = 0.0;
  int count = 0;
  for (double sun_zenith_deg : {89.5, 92.0, 95.0}) {
    const double s = radiansFromDegrees(sun_zenith_deg);
    const glm::dvec3 sun(std::sin(s), 0.0, std::cos(s));
    for (double zenith_deg : {0.0, 45.0, 80.0, 88.0}) {
      for (double azimuth_deg : {0.0, 90.0, 180.0}) {
        const double z = radiansFromDegrees(zenith_deg), az = radiansFromDegrees(azimuth_deg);
        const glm::dvec3 view(std::sin(z) * std::cos(az), std::sin(z) * std::sin(az), std::cos(z));
        const Spectrum xyz = colour.skyRadiance(camera, view, sun).radiance;
        double expected[kCieXyzChannels] = {};
        int i = 0;
        for (const Sky& p : passes) {
          const Spectrum r = p.skyRadiance(camera, view, sun).radiance;
          for (int l = 0; l < p.channelCount(); ++l, ++i) {
            for (int c = 0; c < kCieXyzChannels; ++c) expected[c] += w.colourMatching(c, i) * r[l];
          }
        }
        for (int c = 0; c < kCieXyzChannels; ++c) {
          ASSERT_GT(expected[c], 0.0);
          const double relative = xyz[c] / expected[c] - 1.0;
          EXPECT_LT(std::abs(relative), 0.01)
              << "sun " << sun_zenith_deg << " view " << zenith_deg << " " << azimuth_deg << " channel " << c;
          sum_squares += relative * relative;
          ++count;
        }
      }
    }
  }
  EXPECT_LT(std::sqrt(sum_squares / count), 0.005);
}

TEST_F(ColourBakeTest, FileStatesItsChannelsAndReadsBack) {
  const fs::path path = fs::temp_directory_path() / ("skybake_colour_" + std::to_string(getpid()) + ".exr");
  writeBakeFile(path, colour_->file);
  const BakeFile read = readBakeFile(path);
  const Sky sky = Sky::load(path);
  fs::remove(path);
  EXPECT_EQ(read.format_version, kBakeFormatVersion);
  // Each pass's optical depth, every bit (stored as FLOAT, unrounded).
  ASSERT_EQ(read.wavelength_optical_depth.size(), passes_->size());
  for (size_t g = 0; g < passes_->size(); ++g) {
    EXPECT_EQ(read.wavelength_optical_depth[g].texels, (*passes_)[g].file.tables.optical_depth.texels) << g;
  }
  EXPECT_EQ(sky.contents().wavelength_groups, config_->colour_groups);
  EXPECT_EQ(sky.channels().kind, ChannelKind::CieXyz);
  EXPECT_EQ(sky.channels().names, (std::vector<std::string>{"X", "Y", "Z"}));
  EXPECT_EQ(sky.channels().wavelengths_nm, config_->atmosphere.wavelengths_nm);
  EXPECT_EQ(sky.contents(), colour_->file.contents);
  EXPECT_EQ(sky.luminanceWeights(), Spectrum(0.0f, float(colour::kMaxLuminousEfficacy_lm_per_W), 0.0f, 0.0f));
}

TEST_F(ColourBakeTest, SameTablesForAnyThreadCount) {
  SilentProgress quiet;
  const BakeOutput one = bakeAtmosphere(*config_, 1, quiet);
  forEachTable(one.file.tables, [&](const char* part, const std::vector<Spectrum>& texels) {
    bool equal = false;
    forEachTable(colour_->file.tables, [&](const char* other, const std::vector<Spectrum>& two) {
      if (std::string(other) == part) equal = texels == two;
    });
    EXPECT_TRUE(equal) << part;
  });
  ASSERT_EQ(one.file.wavelength_optical_depth.size(), colour_->file.wavelength_optical_depth.size());
  for (size_t g = 0; g < one.file.wavelength_optical_depth.size(); ++g) {
    EXPECT_EQ(one.file.wavelength_optical_depth[g].texels, colour_->file.wavelength_optical_depth[g].texels) << g;
  }
}

// A colour file as version 9 wrote it, without its wavelengths' optical
// depths (a bake read from one and written again is written so): it reads,
// and its twilight single scattering comes from its X, Y, Z atmosphere.
TEST_F(ColourBakeTest, WithoutWavelengthDepthsIsWrittenAsVersionNine) {
  BakeFile file = colour_->file;
  file.contents.wavelength_groups.clear();
  file.wavelength_optical_depth.clear();
  const fs::path path = fs::temp_directory_path() / ("skybake_colour_v9_" + std::to_string(getpid()) + ".exr");
  writeBakeFile(path, file);
  const BakeFile read = readBakeFile(path);
  fs::remove(path);
  EXPECT_EQ(read.format_version, kFirstWavelengthDepthFormatVersion - 1);
  EXPECT_TRUE(read.contents.wavelength_groups.empty());
  EXPECT_TRUE(read.wavelength_optical_depth.empty());
  EXPECT_TRUE(Sky(read).wavelengthGroupsToXyz().empty());
  EXPECT_EQ(read.tables.single_rayleigh.texels, colour_->file.tables.single_rayleigh.texels);
}

// A file as version 3 wrote it (no skybake:channels) reads as wavelengths.
TEST(ColourBakeFile, VersionThreeFileReadsAsWavelengths) {
  BakeConfig c = parseConfig(colourConfigText(3), "three.toml");
  c.atmosphere = c.colour_groups[0];
  c.colour_groups.clear();
  SilentProgress quiet;
  const BakeOutput bake = bakeAtmosphere(c, 1, quiet);
  const std::string id = std::to_string(getpid());
  const fs::path v4 = fs::temp_directory_path() / ("skybake_v4_" + id + ".exr");
  const fs::path v3 = fs::temp_directory_path() / ("skybake_v3_" + id + ".exr");
  writeBakeFile(v4, bake.file);
  {
    Imf::MultiPartInputFile in(v4.c_str());
    std::vector<Imf::Header> headers;
    for (int p = 0; p < in.parts(); ++p) {
      Imf::Header h = in.header(p);
      ASSERT_NE(h.findTypedAttribute<Imf::StringAttribute>(bake_file::kAttrChannels), nullptr);
      h.erase(bake_file::kAttrChannels);
      h.insert(bake_file::kAttrFormatVersion, Imf::IntAttribute(3));
      headers.push_back(h);
    }
    Imf::MultiPartOutputFile out(v3.c_str(), headers.data(), static_cast<int>(headers.size()));
    for (int p = 0; p < in.parts(); ++p) {
      Imf::InputPart from(in, p);
      Imf::OutputPart to(out, p);
      to.copyPixels(from);
    }
  }
  const BakeFile read = readBakeFile(v3);
  fs::remove(v3);
  fs::remove(v4);
  EXPECT_EQ(read.format_version, 3);
  EXPECT_EQ(read.contents.atmosphere.channel_kind, ChannelKind::Wavelengths);
  // The relabelled file states Bruneton's sun axis, as version 3 files have,
  // and their shape and irradiance rows.
  BakeContents expected = bake.file.contents;
  expected.domain.sun_axis = SunAxisMapping::DistanceToTop;
  expected.domain.irradiance_rows = IrradianceRows::Linear;
  expected.multiple_shape_weight = MultipleShapeWeight::ColumnShare;
  EXPECT_EQ(read.contents, expected);
  EXPECT_EQ(read.tables.single_rayleigh.texels, bake.file.tables.single_rayleigh.texels);
  const Sky sky(read);
  EXPECT_EQ(sky.channels().names, (std::vector<std::string>{"380nm", "580nm", "780nm"}));
}

}  // namespace
}  // namespace skybake

namespace skybake {
namespace {

// An image of a colour bake turns into the linear sRGB of its pixels' X, Y,
// Z; the same spectrum as wavelength samples gives the same colour through
// the same colour-matching weights (both in double from float values: 1e-6
// relative).
TEST(ColourBakeRender, XyzPixelsGiveTheSrgbOfTheirSpectrum) {
  const std::vector<double> nm = {400.0, 450.0, 520.0, 600.0, 700.0};
  const std::vector<float> spectrum = {0.3f, 1.2f, 0.9f, 0.5f, 0.2f};
  const colour::Xyz xyz = colour::SpectralToXyz(nm)(spectrum);
  AtmosphereParameters colour_channels;
  colour_channels.channel_kind = ChannelKind::CieXyz;
  colour_channels.wavelengths_nm = nm;
  const SpectralImage xyz_image{1, 1, 3, {float(xyz.x), float(xyz.y), float(xyz.z)}};
  const SpectralImage spectral_image{1, 1, 5, spectrum};
  const std::vector<float> from_xyz = linearSrgbImage(xyz_image, colour_channels, 1.0);
  const std::vector<float> from_spectrum = linearSrgbImage(spectral_image, nm, 1.0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(from_xyz[c], from_spectrum[c], 1e-6 * std::abs(from_spectrum[c]) + 1e-9);
}

}  // namespace
}  // namespace skybake
