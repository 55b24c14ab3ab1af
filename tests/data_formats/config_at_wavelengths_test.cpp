// A config read at other wavelengths (configAtWavelengths): at its own
// wavelengths it is the config itself, bit for bit; elsewhere each spectrum
// is read at the new wavelengths; a list of differing values is refused,
// naming its key; a flat list stands for its one value everywhere. A config
// stored another way (configFileWithStore) keeps its atmosphere.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "data_formats/config/config.h"
#include "data_formats/config/config_at_wavelengths.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

const fs::path kPresets = fs::path(SKYBAKE_SOURCE_DIR) / "data_formats" / "presets";

// Rayleigh as a power law, Mie by Angstrom's law, the sun and the albedo
// inline, no files: every spectral form that needs none.
constexpr const char* kSpectralConfig = R"(
[channels]
wavelengths_nm = [680, 550, 440]
[planet]
bottom_radius_m = 6360000.0
top_radius_m = 6420000.0
ground_albedo = { wavelengths_nm = [380, 780], values = [0.05, 0.25] }
[sun]
irradiance = { wavelengths_nm = [380, 500, 780], values = [1.1, 2.0, 1.3] }
[rayleigh]
scattering = { at_nm = 550, value = 13.558e-6, exponent = 4 }
density = [{ exp_term = 1.0, exp_scale = -1.25e-4 }]
[mie]
scattering = { at_nm = 550, value = 3.996e-6, angstrom_exponent = 1.3 }
extinction = { at_nm = 550, value = 4.44e-6, angstrom_exponent = 1.3 }
phase_g = 0.8
density = [{ exp_term = 1.0, exp_scale = -8.333e-4 }]
)";

void expectRefusedNaming(const std::string& text, const std::string& key) {
  const std::vector<double> wavelengths = {400.0, 500.0};
  try {
    configAtWavelengths(text, "test.toml", {}, wavelengths);
    ADD_FAILURE() << "accepted:\n" << text;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    const std::string message = e.what();
    EXPECT_NE(message.find("test.toml"), std::string::npos) << message;
    EXPECT_NE(message.find(key), std::string::npos) << message;
    EXPECT_NE(message.find("cannot be read at other wavelengths"), std::string::npos) << message;
  }
}

TEST(ConfigAtWavelengths, AtItsOwnWavelengthsIsTheConfigExactly) {
  const BakeConfig own = parseConfig(kSpectralConfig, "test.toml");
  const BakeConfig again = configAtWavelengths(kSpectralConfig, "test.toml", {}, own.atmosphere.wavelengths_nm);
  EXPECT_EQ(again.atmosphere, own.atmosphere);
  // The shipped spectral Earth, with its spectrum files and a flat albedo list.
  const BakeConfig earth = loadConfigFile(kPresets / "earth_spectral.toml");
  EXPECT_EQ(configFileAtWavelengths(kPresets / "earth_spectral.toml", earth.atmosphere.wavelengths_nm).atmosphere,
            earth.atmosphere);
}

TEST(ConfigAtWavelengths, ReadsEachSpectrumAtTheNewWavelengths) {
  const std::vector<double> wavelengths = {380.0, 500.0, 780.0};
  const AtmosphereParameters a = configAtWavelengths(kSpectralConfig, "test.toml", {}, wavelengths).atmosphere;
  EXPECT_EQ(a.wavelengths_nm, wavelengths);
  // The inline samples themselves, exactly (as floats).
  EXPECT_EQ(a.sun_irradiance[0], 1.1f);
  EXPECT_EQ(a.sun_irradiance[1], 2.0f);
  EXPECT_EQ(a.sun_irradiance[2], 1.3f);
  EXPECT_EQ(a.ground_albedo[0], 0.05f);
  EXPECT_EQ(a.ground_albedo[2], 0.25f);
  // The laws at the new wavelengths; float rounding and pow's last bits:
  // 1e-6 relative, against a wrong exponent's percent.
  EXPECT_NEAR(a.rayleigh_scattering[0], 13.558e-6 * std::pow(550.0 / 380.0, 4.0), 1e-6 * 6e-5);
  EXPECT_NEAR(a.mie_scattering[2], 3.996e-6 * std::pow(550.0 / 780.0, 1.3), 1e-6 * 3e-6);
  EXPECT_EQ(a.bottom_radius_m, 6360000.0);
  EXPECT_EQ(a.mie_phase_g, 0.8);
}

TEST(ConfigAtWavelengths, RefusesListsOfDifferingValuesNamingTheKey) {
  const std::string base = kSpectralConfig;
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string text = base;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  expectRefusedNaming(replaced("irradiance = { wavelengths_nm = [380, 500, 780], values = [1.1, 2.0, 1.3] }",
                               "irradiance = [1.5, 1.9, 2.0]"),
                      "sun.irradiance");
  expectRefusedNaming(replaced("scattering = { at_nm = 550, value = 13.558e-6, exponent = 4 }",
                               "scattering = [5.8e-6, 13.558e-6, 33.1e-6]"),
                      "rayleigh.scattering");
  expectRefusedNaming(replaced("ground_albedo = { wavelengths_nm = [380, 780], values = [0.05, 0.25] }",
                               "ground_albedo = [0.1, 0.2, 0.3]"),
                      "planet.ground_albedo");
}

TEST(ConfigAtWavelengths, AFlatListIsItsValueAtEveryWavelength) {
  std::string text = kSpectralConfig;
  const std::string from = "ground_albedo = { wavelengths_nm = [380, 780], values = [0.05, 0.25] }";
  text.replace(text.find(from), from.size(), "ground_albedo = [0.3, 0.3, 0.3]");
  const std::vector<double> wavelengths = {400.0, 450.0, 500.0, 700.0};
  const AtmosphereParameters a = configAtWavelengths(text, "test.toml", {}, wavelengths).atmosphere;
  for (int c = 0; c < 4; ++c) EXPECT_EQ(a.ground_albedo[c], 0.3f);
}

TEST(ConfigAtWavelengths, SpectraThatDoNotCoverAWavelengthAreRefused) {
  const std::vector<double> wavelengths = {370.0};
  try {
    configAtWavelengths(kSpectralConfig, "test.toml", {}, wavelengths);
    ADD_FAILURE() << "a wavelength outside the inline spectra was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not extrapolated"), std::string::npos) << e.what();
  }
}

// configFileWithStore: the colour preset stored as a spectral bake is the
// same atmosphere on the same wavelengths, grouped into the same passes;
// only what the file keeps differs.
TEST(ConfigFileWithStore, AColourConfigAsASpectralBakeHasTheSameGroups) {
  const fs::path colour_path = kPresets / "earth_colour.toml";
  const BakeConfig colour = loadConfigFile(colour_path);
  ASSERT_TRUE(colour.atmosphere.storesCieXyz());
  const BakeConfig spectral = configFileWithStore(colour_path, "spectral");
  EXPECT_TRUE(spectral.atmosphere.storesLaneGroups());
  EXPECT_EQ(spectral.atmosphere.wavelengths_nm, colour.atmosphere.wavelengths_nm);
  EXPECT_EQ(spectral.colour_groups, colour.colour_groups);
  EXPECT_EQ(spectral.sizes, colour.sizes);
  // The spectral preset of the same atmosphere is what it gives.
  EXPECT_EQ(spectral.colour_groups, loadConfigFile(kPresets / "earth_spectral_16.toml").colour_groups);
  try {
    configFileWithStore(colour_path, "rgb");
    ADD_FAILURE() << "store \"rgb\" accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("channels.store = \"rgb\""), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace skybake
