// Config parsing and validation: presets load, the canonical form round-trips,
// and every class of bad input is refused with a message naming the key.
#include <gtest/gtest.h>

#include <string>

#include "data_formats/config.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

const std::string kMinimal = R"(
[channels]
wavelengths_nm = [550.0]
[planet]
bottom_radius_m = 6360000.0
top_radius_m = 6420000.0
[sun]
irradiance = [1.8]
)";

// Parses `text` expecting a BadInput error whose message contains every
// string in `fragments`.
void expectRejected(const std::string& text, std::initializer_list<std::string> fragments) {
  try {
    parseConfig(text, "test.toml");
    FAIL() << "accepted:\n" << text;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    const std::string message = e.what();
    EXPECT_NE(message.find("test.toml"), std::string::npos) << message;
    for (const std::string& f : fragments) EXPECT_NE(message.find(f), std::string::npos) << message;
  }
}

// kMinimal with `from` replaced by `to`.
std::string edited(const std::string& from, const std::string& to) {
  std::string text = kMinimal;
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos);
  return text.replace(at, from.size(), to);
}

TEST(Config, BuiltinEarthHasBrunetonValues) {
  const BakeConfig c = builtinEarthConfig();
  EXPECT_EQ(c.name, "earth");
  EXPECT_EQ(c.atmosphere.channelCount(), 3);
  EXPECT_DOUBLE_EQ(c.atmosphere.bottom_radius_m, 6360000.0);
  EXPECT_FLOAT_EQ(c.atmosphere.rayleigh_scattering[2], 33.1e-6f);
  EXPECT_DOUBLE_EQ(c.atmosphere.mie_phase_g, 0.8);
  ASSERT_EQ(c.atmosphere.absorption_density.size(), 2u);
  EXPECT_DOUBLE_EQ(c.atmosphere.absorption_density[0].width_m, 25000.0);
  EXPECT_EQ(c.sizes.scattering_mu, 128);
  EXPECT_EQ(c.bake.orders, 4);
}

TEST(Config, PresetsLoad) {
  for (const char* name : {"earth", "earth_hazy", "mars"}) {
    const BakeConfig c = loadConfigFile(std::string(SKYBAKE_SOURCE_DIR) + "/data_formats/presets/" + name + ".toml");
    EXPECT_EQ(c.name, name);
  }
}

TEST(Config, CanonicalTomlRoundTripsExactly) {
  for (const BakeConfig& original : {builtinEarthConfig(), parseConfig(kMinimal, "minimal")}) {
    const std::string text = configToToml(original);
    const BakeConfig again = parseConfig(text, "round trip");
    EXPECT_EQ(configToToml(again), text);
    EXPECT_EQ(again.atmosphere.sun_irradiance, original.atmosphere.sun_irradiance);
    EXPECT_EQ(again.atmosphere.mie_density.size(), original.atmosphere.mie_density.size());
    EXPECT_EQ(again.atmosphere.bottom_radius_m, original.atmosphere.bottom_radius_m);
  }
}

TEST(Config, MinimalConfigGetsDefaults) {
  const BakeConfig c = parseConfig(kMinimal, "minimal");
  EXPECT_EQ(c.atmosphere.rayleigh_scattering[0], 0.0f);
  EXPECT_TRUE(c.atmosphere.mie_density.empty());
  EXPECT_EQ(c.bake.orders, 4);
  EXPECT_DOUBLE_EQ(c.atmosphere.sun_max_zenith_deg, 102.0);
}

TEST(Config, RejectsSyntaxErrorsWithLine) {
  expectRejected(kMinimal + "\n[bake\n", {"test.toml:", "syntax"});
}

TEST(Config, RejectsUnknownKeys) {
  expectRejected(kMinimal + "\n[bake]\norderz = 3\n", {"bake.orderz", "unknown key"});
  expectRejected(kMinimal + "\ncolour = 1\n", {"colour", "unknown key"});
  expectRejected(kMinimal + "\n[rayleigh]\nscattering = [1e-5]\ndensity = [{ exp_trm = 1.0 }]\n",
                 {"rayleigh.density[0].exp_trm", "unknown key"});
}

TEST(Config, RejectsMissingRequiredKeys) {
  expectRejected(edited("top_radius_m = 6420000.0", ""), {"planet.top_radius_m", "missing"});
  expectRejected(edited("[sun]\nirradiance = [1.8]", "[sun]"), {"sun.irradiance", "missing"});
  expectRejected(kMinimal + "\n[mie]\nscattering = [1e-5]\nphase_g = 0.8\n", {"mie.density", "missing"});
}

TEST(Config, RejectsTopNotAboveBottom) {
  expectRejected(edited("top_radius_m = 6420000.0", "top_radius_m = 6360000.0"),
                 {"planet.top_radius_m", "6360000", "greater than"});
  expectRejected(edited("top_radius_m = 6420000.0", "top_radius_m = 100.0"), {"planet.top_radius_m"});
}

TEST(Config, RejectsNegativeCoefficientsAndAlbedo) {
  expectRejected(kMinimal + "\n[rayleigh]\nscattering = [-1e-6]\ndensity = []\n",
                 {"rayleigh.scattering[0]", "-1e-06", ">= 0"});
  expectRejected(edited("top_radius_m = 6420000.0", "top_radius_m = 6420000.0\nground_albedo = [-0.1]"),
                 {"planet.ground_albedo[0]", ">= 0"});
  expectRejected(kMinimal + "\n[absorption]\nextinction = [-2e-6]\ndensity = []\n",
                 {"absorption.extinction[0]"});
  expectRejected(kMinimal + "\n[mie]\nscattering = [2e-5]\nextinction = [1e-5]\nphase_g = 0.7\ndensity = []\n",
                 {"mie.extinction[0]", ">= mie.scattering"});
}

TEST(Config, RejectsPhaseGOutsideOpenUnitInterval) {
  for (const char* g : {"1.0", "1.2", "-1.0"}) {
    expectRejected(kMinimal + "\n[mie]\nscattering = [2e-5]\nphase_g = " + g + "\ndensity = []\n",
                   {"mie.phase_g", "(-1, 1)"});
  }
}

TEST(Config, RejectsZeroAndAbsurdSizes) {
  expectRejected(kMinimal + "\n[resolution]\ntransmittance = [0, 64]\n", {"resolution.transmittance[0]", "= 0"});
  expectRejected(kMinimal + "\n[resolution]\nscattering = { mu = 127 }\n", {"resolution.scattering.mu", "even"});
  expectRejected(kMinimal + "\n[resolution]\nscattering = { r = 100000 }\n", {"resolution.scattering.r"});
  expectRejected(kMinimal + "\n[resolution]\nscattering = { r = 1024, mu = 1024, mu_s = 1024 }\n",
                 {"resolution.scattering", "texels"});
  expectRejected(kMinimal + "\n[resolution]\nirradiance = [64, 16, 3]\n", {"resolution.irradiance"});
  expectRejected(kMinimal + "\n[bake]\norders = 0\n", {"bake.orders"});
  expectRejected(kMinimal + "\n[bake]\nprecision = \"double\"\n", {"bake.precision", "double"});
}

TEST(Config, RejectsNanAndInfinity) {
  expectRejected(edited("bottom_radius_m = 6360000.0", "bottom_radius_m = nan"), {"planet.bottom_radius_m", "finite"});
  expectRejected(edited("irradiance = [1.8]", "irradiance = [inf]"), {"sun.irradiance[0]", "finite"});
  expectRejected(kMinimal + "\n[rayleigh]\nscattering = [1e-5]\ndensity = [{ exp_scale = -inf }]\n",
                 {"rayleigh.density[0].exp_scale", "finite"});
}

TEST(Config, RejectsWrongTypesAndChannelCounts) {
  expectRejected(edited("bottom_radius_m = 6360000.0", "bottom_radius_m = \"big\""),
                 {"planet.bottom_radius_m", "number"});
  expectRejected(edited("irradiance = [1.8]", "irradiance = [1.8, 1.9]"),
                 {"sun.irradiance", "one per wavelength"});
  expectRejected(edited("wavelengths_nm = [550.0]", "wavelengths_nm = [400.0, 450.0, 500.0, 550.0, 600.0]"),
                 {"channels.wavelengths_nm", "1 to 4"});
}

TEST(Config, MissingFileIsBadInput) {
  try {
    loadConfigFile("/nonexistent/dir/x.toml");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/x.toml"), std::string::npos);
  }
}

}  // namespace
}  // namespace skybake
