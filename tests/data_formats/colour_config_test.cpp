// The config of a colour bake: channels.store, its wavelength limits, its
// passes (BakeConfig::colour_groups) and its canonical TOML.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "data_formats/config/config.h"
#include "expect_config_rejected.h"

namespace skybake {
namespace {

// The built-in Earth's canonical text with its [channels] table and its
// per-wavelength quantities given as laws and a flat spectrum, so that any
// number of wavelengths reads.
std::string earthWith(const std::string& channels) {
  return R"(name = "colour"
[channels]
)" + channels +
         R"(
[planet]
bottom_radius_m = 6360000.0
top_radius_m = 6420000.0
ground_albedo = { wavelengths_nm = [300, 900], values = [0.1, 0.1] }
[sun]
irradiance = { wavelengths_nm = [300, 900], values = [1.5, 1.9] }
[rayleigh]
scattering = { at_nm = 550, value = 13.558e-6, exponent = 4 }
density = [{ exp_term = 1.0, exp_scale = -1.25e-4 }]
[mie]
scattering = { at_nm = 550, value = 3.996e-6, angstrom_exponent = 0.0 }
phase_g = 0.8
density = [{ exp_term = 1.0, exp_scale = -8.333e-4 }]
)";
}

TEST(ColourConfig, MoreThanFourWavelengthsNeedColourStorage) {
  test::expectConfigRejected(earthWith("wavelengths_nm = { min_nm = 380, max_nm = 780, count = 5 }"),
                             {"channels.wavelengths_nm", "5 wavelengths, but a wavelength bake holds at most 4",
                              "\"spectral\"", "\"cie_xyz\""});
}

TEST(ColourConfig, ColourStorageTakesAtMostSixtyFour) {
  test::expectConfigRejected(
      earthWith("wavelengths_nm = { min_nm = 380, max_nm = 780, count = 65 }\nstore = \"cie_xyz\""),
      {"channels.wavelengths_nm", "65 wavelengths", "integrates at most 64"});
  const BakeConfig c =
      parseConfig(earthWith("wavelengths_nm = { min_nm = 380, max_nm = 780, count = 64 }\nstore = \"cie_xyz\""), "c");
  EXPECT_EQ(c.colour_groups.size(), 16u);
}

TEST(ColourConfig, UnknownStoreIsRefused) {
  test::expectConfigRejected(earthWith("wavelengths_nm = [440, 550, 680]\nstore = \"rgb\""),
                             {"channels.store", "'rgb'", "cie_xyz"});
}

TEST(ColourConfig, CombinedSingleMieIsRefused) {
  test::expectConfigRejected(
      earthWith("wavelengths_nm = [420, 550, 680]\nstore = \"cie_xyz\"") + "[bake]\ncombined_single_mie = true\n",
      {"bake.combined_single_mie", "colour bake"});
}

// Wavelengths short of the colour-matching functions' lobes would bake a
// grey sky (kColourSpanShortest_nm, kColourSpanLongest_nm).
TEST(ColourConfig, WavelengthsThatDoNotSpanTheColourMatchingFunctionsAreRefused) {
  for (const auto& [wavelengths, value] :
       {std::pair{"{ min_nm = 700, max_nm = 780, count = 3 }", "700 to 780 nm"},
        std::pair{"[550]", "550 nm (one wavelength)"}, std::pair{"[430, 550, 680]", "430 to 680 nm"},
        std::pair{"[420, 550, 630]", "420 to 630 nm"}}) {
    SCOPED_TRACE(wavelengths);
    test::expectConfigRejected(
        earthWith(std::string("wavelengths_nm = ") + wavelengths + "\nstore = \"cie_xyz\""),
        {"channels.wavelengths_nm", value, "from 420 nm or shorter to 640 nm or longer", "grey"});
  }
  // The ends themselves are enough, in any order.
  const BakeConfig at_the_ends = parseConfig(earthWith("wavelengths_nm = [640, 420]\nstore = \"cie_xyz\""), "c");
  EXPECT_EQ(at_the_ends.colour_groups.size(), 1u);
  // A wavelength bake of one wavelength is not a colour and stays allowed.
  EXPECT_NO_THROW(parseConfig(earthWith("wavelengths_nm = [550]"), "c"));
}

TEST(ColourConfig, PassesHoldEveryWavelengthsQuantitiesInOrder) {
  const BakeConfig c =
      parseConfig(earthWith("wavelengths_nm = { min_nm = 380, max_nm = 780, count = 15 }\nstore = \"cie_xyz\""), "c");
  EXPECT_EQ(c.atmosphere.channel_kind, ChannelKind::CieXyz);
  EXPECT_EQ(c.atmosphere.channelCount(), 3);
  ASSERT_EQ(c.colour_groups.size(), 4u);
  size_t i = 0;
  for (const AtmosphereParameters& g : c.colour_groups) {
    EXPECT_EQ(g.channel_kind, ChannelKind::Wavelengths);
    EXPECT_EQ(g.channelCount(), i < 12 ? 4 : 3);
    EXPECT_EQ(g.rayleigh_density, c.atmosphere.rayleigh_density);
    for (int l = 0; l < g.channelCount(); ++l, ++i) {
      const double nm = c.atmosphere.wavelengths_nm[i];
      EXPECT_EQ(g.wavelengths_nm[l], nm);
      // The lambda^-4 law in double, stored in float.
      EXPECT_EQ(g.rayleigh_scattering[l], static_cast<float>(13.558e-6 * std::pow(550.0 / nm, 4.0)));
      EXPECT_EQ(g.mie_extinction[l], g.mie_scattering[l]);  // the default
    }
  }
  EXPECT_EQ(i, 15u);
}

TEST(ColourConfig, CanonicalTextReadsBackToItself) {
  const BakeConfig c =
      parseConfig(earthWith("wavelengths_nm = { min_nm = 380, max_nm = 780, count = 7 }\nstore = \"cie_xyz\""), "c");
  const std::string canonical = configToToml(c);
  EXPECT_NE(canonical.find("store = \"cie_xyz\""), std::string::npos);
  const BakeConfig again = parseConfig(canonical, "again");
  EXPECT_EQ(configToToml(again), canonical);
  ASSERT_EQ(again.colour_groups.size(), c.colour_groups.size());
  for (size_t g = 0; g < c.colour_groups.size(); ++g) EXPECT_EQ(again.colour_groups[g], c.colour_groups[g]);
  // A wavelength bake's text has no store line (its canonical text is unchanged).
  EXPECT_EQ(configToToml(builtinEarthConfig()).find("store ="), std::string::npos);
}

TEST(ColourConfig, ShippedColourPresetReads) {
  const std::filesystem::path presets = std::filesystem::path(SKYBAKE_SOURCE_DIR) / "data_formats" / "presets";
  const BakeConfig c = loadConfigFile(presets / "earth_colour.toml");
  EXPECT_EQ(c.atmosphere.wavelengths_nm.size(), 16u);
  EXPECT_EQ(c.atmosphere.wavelengths_nm.front(), 380.0);
  EXPECT_EQ(c.atmosphere.wavelengths_nm.back(), 780.0);
  EXPECT_EQ(c.colour_groups.size(), 4u);
}

}  // namespace
}  // namespace skybake
