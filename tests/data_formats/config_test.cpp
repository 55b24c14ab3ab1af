// Config parsing and validation: presets load, the canonical form round-trips,
// and every class of bad input is refused with a message naming the key.
#include <gtest/gtest.h>

#include <string>

#include "data_formats/config/config.h"
#include "data_formats/error.h"
#include "expect_config_rejected.h"

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

void expectRejected(const std::string& text, std::initializer_list<std::string> fragments) {
  test::expectConfigRejected(text, fragments);
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
  EXPECT_EQ(c.sizes.scattering_nu, 16);
  EXPECT_EQ(c.bake.orders, 6);
}

TEST(Config, PresetsLoad) {
  for (const char* name : {"earth", "earth_hazy", "mars", "earth_spectral", "earth_colour", "earth_twilight"}) {
    const BakeConfig c = loadConfigFile(std::string(SKYBAKE_SOURCE_DIR) + "/data_formats/presets/" + name + ".toml");
    EXPECT_EQ(c.name, name);
  }
}

// The twilight preset is the built-in Earth with twice its sun and view-sun
// axes, nothing else: the two files cannot drift apart.
TEST(Config, TwilightPresetIsTheBuiltInEarthWithFinerSunAxes) {
  BakeConfig twilight = loadConfigFile(std::string(SKYBAKE_SOURCE_DIR) + "/data_formats/presets/earth_twilight.toml");
  const BakeConfig earth = builtinEarthConfig();
  EXPECT_EQ(twilight.sizes.scattering_mu_s, 2 * earth.sizes.scattering_mu_s);
  EXPECT_EQ(twilight.sizes.scattering_nu, 2 * earth.sizes.scattering_nu);
  twilight.name = earth.name;
  twilight.sizes.scattering_mu_s = earth.sizes.scattering_mu_s;
  twilight.sizes.scattering_nu = earth.sizes.scattering_nu;
  EXPECT_EQ(configToToml(twilight), configToToml(earth));
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

TEST(Config, AutomaticOrdersParseAndRoundTrip) {
  const BakeConfig c =
      parseConfig(kMinimal + "[bake]\norders = \"auto\"\norder_tolerance = 0.002\nmax_orders = 20\n", "auto");
  EXPECT_TRUE(c.bake.auto_orders);
  EXPECT_DOUBLE_EQ(c.bake.order_tolerance, 0.002);
  EXPECT_EQ(c.bake.max_orders, 20);
  const std::string text = configToToml(c);
  const BakeConfig again = parseConfig(text, "round trip");
  EXPECT_TRUE(again.bake.auto_orders);
  EXPECT_DOUBLE_EQ(again.bake.order_tolerance, 0.002);
  EXPECT_EQ(again.bake.max_orders, 20);
  EXPECT_EQ(configToToml(again), text);
}

TEST(Config, SceneOutputsParseAndRoundTrip) {
  const BakeConfig all = parseConfig(kMinimal, "minimal");
  EXPECT_TRUE(all.scene.radiance_to_points);
  EXPECT_TRUE(all.scene.ground_irradiance);
  // The default writes no [scene], so existing canonical texts (and the
  // reference cache keys hashed from them) stay as they were.
  EXPECT_EQ(configToToml(all).find("[scene]"), std::string::npos);

  const BakeConfig sky_only = parseConfig(kMinimal + "[scene]\noutputs = [\"sky_radiance\"]\n", "sky only");
  EXPECT_FALSE(sky_only.scene.radiance_to_points);
  EXPECT_FALSE(sky_only.scene.ground_irradiance);
  const BakeConfig ground =
      parseConfig(kMinimal + "[scene]\noutputs = [\"ground_irradiance\", \"sky_radiance\"]\n", "ground");
  EXPECT_FALSE(ground.scene.radiance_to_points);
  EXPECT_TRUE(ground.scene.ground_irradiance);
  for (const BakeConfig& c : {sky_only, ground}) {
    const std::string text = configToToml(c);
    const BakeConfig again = parseConfig(text, "round trip");
    EXPECT_EQ(again.scene.radiance_to_points, c.scene.radiance_to_points);
    EXPECT_EQ(again.scene.ground_irradiance, c.scene.ground_irradiance);
    EXPECT_EQ(configToToml(again), text);
  }
}

TEST(Config, CombinedSingleMieParsesRoundTripsAndNeedsAFreeChannel) {
  EXPECT_FALSE(parseConfig(kMinimal, "minimal").bake.combined_single_mie);
  // Off by default and then not written, so canonical texts stay as they were.
  EXPECT_EQ(configToToml(parseConfig(kMinimal, "minimal")).find("combined_single_mie"), std::string::npos);
  const std::string density = "density = [{ exp_term = 1.0, exp_scale = -1.25e-4 }]\n";
  const std::string mie = "[mie]\nscattering = [4e-6]\nextinction = [4.4e-6]\nphase_g = 0.8\n" + density +
                          "[rayleigh]\nscattering = [1.3e-5]\n" + density;
  const BakeConfig combined = parseConfig(kMinimal + mie + "[bake]\ncombined_single_mie = true\n", "combined");
  EXPECT_TRUE(combined.bake.combined_single_mie);
  EXPECT_TRUE(parseConfig(configToToml(combined), "round trip").bake.combined_single_mie);

  expectRejected(kMinimal + "[bake]\ncombined_single_mie = 1\n", {"bake.combined_single_mie", "true or false"});
  // Four wavelengths fill every channel: no room for the Mie one.
  const std::string four = R"(
[channels]
wavelengths_nm = [680.0, 550.0, 440.0, 400.0]
[planet]
bottom_radius_m = 6360000.0
top_radius_m = 6420000.0
[sun]
irradiance = [1.5, 1.8, 1.9, 1.7]
[rayleigh]
scattering = [5.8e-6, 1.36e-5, 3.3e-5, 4.4e-5]
density = [{ exp_term = 1.0, exp_scale = -1.25e-4 }]
[mie]
scattering = [4e-6, 4e-6, 4e-6, 4e-6]
extinction = [4.4e-6, 4.4e-6, 4.4e-6, 4.4e-6]
phase_g = 0.8
density = [{ exp_term = 1.0, exp_scale = -8.3e-4 }]
[bake]
combined_single_mie = true
)";
  expectRejected(four, {"bake.combined_single_mie", "at most 3 wavelengths", "has 4"});
  // The stored channel is the first: it needs Mie and Rayleigh scattering.
  std::string no_first = four;
  no_first.replace(no_first.find("[680.0, 550.0, 440.0, 400.0]"), 28, "[680.0, 550.0, 440.0]");
  no_first.replace(no_first.find("[1.5, 1.8, 1.9, 1.7]"), 20, "[1.5, 1.8, 1.9]");
  no_first.replace(no_first.find("[5.8e-6, 1.36e-5, 3.3e-5, 4.4e-5]"), 33, "[5.8e-6, 1.36e-5, 3.3e-5]");
  no_first.replace(no_first.find("[4e-6, 4e-6, 4e-6, 4e-6]"), 24, "[0.0, 4e-6, 4e-6]");
  no_first.replace(no_first.find("[4.4e-6, 4.4e-6, 4.4e-6, 4.4e-6]"), 32, "[4.4e-6, 4.4e-6, 4.4e-6]");
  expectRejected(no_first, {"bake.combined_single_mie", "first wavelength (680 nm)"});
  // Without Mie scattering there is nothing to combine: accepted.
  EXPECT_NO_THROW(parseConfig(kMinimal + "[bake]\ncombined_single_mie = true\n", "no mie"));
}

TEST(Config, RejectsBadSceneOutputs) {
  expectRejected(kMinimal + "[scene]\noutputs = \"sky_radiance\"\n", {"scene.outputs", "must be a list"});
  expectRejected(kMinimal + "[scene]\noutputs = [\"sky_radiance\", \"clouds\"]\n",
                 {"scene.outputs", "clouds", "must be a list of"});
  expectRejected(kMinimal + "[scene]\noutputs = [\"ground_irradiance\"]\n",
                 {"scene.outputs", "must include \"sky_radiance\""});
  expectRejected(kMinimal + "[scene]\naltitude = 3\n", {"scene.altitude", "unknown key"});
}

TEST(Config, SceneRangesParseAndRoundTrip) {
  const BakeConfig whole = parseConfig(kMinimal, "minimal");
  EXPECT_FALSE(whole.scene_ranges.narrows());
  const BakeConfig c = parseConfig(kMinimal +
                                       "[scene]\naltitude_range_m = [0, 2000.5]\nsun_zenith_range_deg = [10, 90]\n"
                                       "[resolution.iteration]\nr = 16\nmu_s = 24\n",
                                   "ranges");
  ASSERT_TRUE(c.scene_ranges.altitude_m && c.scene_ranges.sun_zenith_deg && c.sizes.iteration);
  EXPECT_EQ((*c.scene_ranges.altitude_m)[1], 2000.5);
  EXPECT_EQ((*c.scene_ranges.sun_zenith_deg)[0], 10.0);
  // Unnamed iteration sizes are left to the bake.
  constexpr int kChosen = TextureSizes::kChosenByTheBake;
  EXPECT_EQ(*c.sizes.iteration, (std::array<int, 4>{16, kChosen, 24, kChosen}));
  EXPECT_FALSE(c.sizes.scene.has_value());
  const std::string text = configToToml(c);
  const BakeConfig again = parseConfig(text, "round trip");
  EXPECT_EQ(again.scene_ranges.altitude_m, c.scene_ranges.altitude_m);
  EXPECT_EQ(again.scene_ranges.sun_zenith_deg, c.scene_ranges.sun_zenith_deg);
  EXPECT_EQ(again.sizes.iteration, c.sizes.iteration);
  EXPECT_EQ(configToToml(again), text);
  // resolution.scene: the same, and round-trips beside the iteration.
  const BakeConfig given = parseConfig(kMinimal + "[resolution.scene]\nr = 8\nmu = 96\nmu_s = 25\nnu = 12\n", "scene");
  EXPECT_EQ(given.sizes.scene, (std::array<int, 4>{8, 96, 25, 12}));
  EXPECT_EQ(parseConfig(configToToml(given), "round trip").sizes.scene, given.sizes.scene);
  // Views below the horizon: on unless the scene says otherwise.
  EXPECT_TRUE(c.scene_ranges.views_below_horizon);
  const BakeConfig sky = parseConfig(kMinimal + "[scene]\nviews_below_horizon = false\n", "sky views");
  EXPECT_FALSE(sky.scene_ranges.views_below_horizon);
  EXPECT_TRUE(sky.scene_ranges.narrows());
  EXPECT_FALSE(parseConfig(configToToml(sky), "round trip").scene_ranges.views_below_horizon);
}

TEST(Config, RejectsBadSceneRanges) {
  expectRejected(kMinimal + "[scene]\naltitude_range_m = [0, 2000, 3000]\n",
                 {"scene.altitude_range_m", "must be [low, high]"});
  expectRejected(kMinimal + "[scene]\naltitude_range_m = [2000, 2000]\n",
                 {"scene.altitude_range_m", "low end must be below"});
  expectRejected(kMinimal + "[scene]\naltitude_range_m = [-5, 2000]\n", {"scene.altitude_range_m[0]", "-5"});
  expectRejected(kMinimal + "[scene]\naltitude_range_m = [1e9, 2e9]\n",
                 {"scene.altitude_range_m[0]", "below the top of the atmosphere"});
  expectRejected(kMinimal + "[scene]\nsun_zenith_range_deg = [0, 150]\n",
                 {"scene.sun_zenith_range_deg[1]", "150", "sun.max_zenith_deg"});
  expectRejected(kMinimal + "[scene]\nsun_zenith_range_deg = [\"low\", 90]\n",
                 {"scene.sun_zenith_range_deg[0]", "must be a number"});
  expectRejected(kMinimal + "[scene]\nviews_below_horizon = \"no\"\n",
                 {"scene.views_below_horizon", "must be true or false"});
  expectRejected(kMinimal + "[scene]\nsun_zenith_range_deg = [0, 90]\n[resolution.iteration]\nmu = 33\n",
                 {"resolution.iteration.mu", "33", "must be even"});
  expectRejected(kMinimal + "[resolution.scene]\nr = 1\n", {"resolution.scene.r", "1"});
  expectRejected(kMinimal + "[resolution.scene]\nmu = 33\n", {"resolution.scene.mu", "33", "must be even"});
  expectRejected(kMinimal + "[resolution.scene]\nheight = 3\n", {"resolution.scene.height", "unknown key"});
}

TEST(Config, RejectsBadOrderSettings) {
  expectRejected(kMinimal + "[bake]\norders = \"many\"\n", {"bake.orders", "many", "\"auto\""});
  expectRejected(kMinimal + "[bake]\norders = \"auto\"\norder_tolerance = 0.0\n",
                 {"bake.order_tolerance", "must be in"});
  expectRejected(kMinimal + "[bake]\norder_tolerance = 0.9\n", {"bake.order_tolerance", "0.9"});
  expectRejected(kMinimal + "[bake]\nmax_orders = 1\n", {"bake.max_orders", "1", "must be in [2, 1000]"});
}

TEST(Config, StoredFractionBitsDefaultRoundTripAndRange) {
  EXPECT_EQ(parseConfig(kMinimal, "minimal").bake.stored_fraction_bits, kDefaultStoredFractionBits);
  const BakeConfig exact = parseConfig(kMinimal + "[bake]\nstored_fraction_bits = 23\n", "exact");
  EXPECT_EQ(exact.bake.stored_fraction_bits, 23);
  EXPECT_EQ(parseConfig(configToToml(exact), "round trip").bake.stored_fraction_bits, 23);
  // The default is left out of the canonical text, which keys reference caches.
  EXPECT_EQ(configToToml(parseConfig(kMinimal, "minimal")).find("stored_fraction_bits"), std::string::npos);
  expectRejected(kMinimal + "[bake]\nstored_fraction_bits = 9\n",
                 {"bake.stored_fraction_bits", "9", "must be in [10, 23]"});
  expectRejected(kMinimal + "[bake]\nstored_fraction_bits = 24\n", {"bake.stored_fraction_bits", "24"});
  expectRejected(kMinimal + "[bake]\nstored_fraction_bits = 16.5\n", {"bake.stored_fraction_bits", "16.5"});
}

TEST(Config, MinimalConfigGetsDefaults) {
  const BakeConfig c = parseConfig(kMinimal, "minimal");
  EXPECT_EQ(c.atmosphere.rayleigh_scattering[0], 0.0f);
  EXPECT_TRUE(c.atmosphere.mie_density.empty());
  EXPECT_EQ(c.bake.orders, 6);
  EXPECT_DOUBLE_EQ(c.atmosphere.sun_max_zenith_deg, 111.0);
}

TEST(Config, RejectsSyntaxErrorsWithLine) { expectRejected(kMinimal + "\n[bake\n", {"test.toml:", "syntax"}); }

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
  expectRejected(kMinimal + "\n[absorption]\nextinction = [-2e-6]\ndensity = []\n", {"absorption.extinction[0]"});
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
  expectRejected(edited("irradiance = [1.8]", "irradiance = [1.8, 1.9]"), {"sun.irradiance", "one per wavelength"});
  expectRejected(edited("wavelengths_nm = [550.0]", "wavelengths_nm = [400.0, 450.0, 500.0, 550.0, 600.0]"),
                 {"channels.wavelengths_nm", "5 wavelengths", "at most 4"});
  expectRejected(edited("wavelengths_nm = [550.0]", "wavelengths_nm = []"),
                 {"channels.wavelengths_nm", "at least one wavelength"});
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

// Inputs found by tests/fuzz/fuzz_config.

TEST(Config, NameWithControlCharactersRoundTrips) {
  // The canonical TOML is what a bake file stores: a raw DEL in it made the
  // file's own config unreadable.
  BakeConfig c = parseConfig(kMinimal, "minimal");
  c.name = std::string(
      "a\x7f"
      "b\x01"
      "c\td\"e\\f");
  const BakeConfig again = parseConfig(configToToml(c), "round trip");
  EXPECT_EQ(again.name, c.name);
}

TEST(Config, NonAsciiIsAcceptedInStringsAndComments) {
  const std::string comment = "# Ünïcödé — a comment\n";
  EXPECT_EQ(parseConfig(comment + "name = \"café — Ελλάδα\"  # é\n" + kMinimal, "a").name, "café — Ελλάδα");
  EXPECT_EQ(parseConfig(comment + "name = \"\"\"\\\n  text: é\"\"\"\n" + kMinimal, "b").name, "text: é");
  EXPECT_EQ(parseConfig(comment + "name = \'\'\'é\n§\'\'\'\n" + kMinimal, "c").name, "é\n§");
}

TEST(Config, RejectsNonAsciiOutsideStringsWithPosition) {
  // The TOML parser's whitespace test is undefined behaviour on these
  // characters, so they must be refused before it runs.
  expectRejected(kMinimal + "\n[bake]\norders = 4é\n", {"test.toml:11:11:", "non-ASCII"});
  expectRejected("\xcc\xaa", {"test.toml:1:1:", "non-ASCII"});
  expectRejected("[bakë]\n", {"test.toml:1:5:", "non-ASCII"});
}

TEST(Config, RejectsNonAsciiAfterBackslashInMultiLineString) {
  expectRejected("name = \"\"\"\\\n  §\"\"\"\n" + kMinimal, {"test.toml:2:3:", "line-ending backslash"});
  // The parser skips its non-ASCII whitespace (here U+FEFF) as it skips spaces.
  expectRejected("name = \"\"\"\\\n \xEF\xBB\xBF §\"\"\"\n" + kMinimal, {"test.toml:2:4:", "U+00A7"});
  expectRejected("name = \"\"\"\\§\"\"\"\n" + kMinimal, {"test.toml:1:12:", "escape code"});
}

TEST(Config, DescribesArraysOfSmallAndExtremeNumbers) {
  // Wrong-length arrays are quoted in the message; toml++'s own formatter is
  // undefined behaviour on numbers between -1 and 1 and on INT64_MIN.
  expectRejected(edited("irradiance = [1.8]", "irradiance = [1e-7, -9223372036854775808, 0.5]"),
                 {"sun.irradiance = [", "-9223372036854775808", "one per wavelength"});
  expectRejected(edited("irradiance = [1.8]", "irradiance = [[0.25, { a = -0.5 }], 2]"),
                 {"sun.irradiance[0] = [0.25, { a = -0.5 }]", "number"});
}

}  // namespace
}  // namespace skybake

namespace skybake {
namespace {

std::string repeated(const std::string& piece, int times) {
  std::string out;
  for (int i = 0; i < times; ++i) out += piece;
  return out;
}

// Deep nesting is refused before the TOML parser sees it: the parser
// recurses once per level, and 50000 levels (100 kB) overflowed its stack.
// Each form of nesting is refused alone, at that depth and just past the
// limit, and the depth a config really has is accepted.
TEST(Config, RefusesNestingDeeperThanTheParserCanTakeBeforeParsing) {
  const char* kDeep = "nested more than 32 levels deep";
  for (int levels : {33, 50000}) {
    const std::string dots = repeated("a.", levels - 1) + "a";
    expectRejected(kMinimal + dots + " = 1\n", {kDeep});            // a dotted key
    expectRejected(kMinimal + "[" + dots + "]\nb = 1\n", {kDeep});  // a table header
    expectRejected(kMinimal + "x = " + repeated("{a = ", levels) + "1" + repeated("}", levels) + "\n",
                   {kDeep});                                                                            // inline tables
    expectRejected(kMinimal + "x = " + repeated("[", levels) + repeated("]", levels) + "\n", {kDeep});  // arrays
  }
  // Levels add up across the forms: a table header (11 levels), a dotted key
  // (11, its last the first inline table) and 11 more inline tables: 33.
  expectRejected(kMinimal + "[" + repeated("a.", 10) + "a]\n" + repeated("b.", 10) + "b = " + repeated("{c = ", 12) +
                     "1" + repeated("}", 12) + "\n",
                 {kDeep});
  // 32 levels in all pass the check (and fail later, as the unknown keys
  // they are): kMinimal ends in a [table], one level, and 31 more below it.
  expectRejected(kMinimal + "x = " + repeated("{a = ", 31) + "1" + repeated("}", 31) + "\n", {"unknown"});
  expectRejected(kMinimal + repeated("a.", 30) + "a = 1\n", {"unknown"});
}

}  // namespace
}  // namespace skybake

namespace skybake {
namespace {

// Numbers whose products the float tables cannot hold are refused by the
// config check, naming the key: with 3e38 the bake wrote a file its own
// reader refused (a non-finite optical depth or radiance).
TEST(Config, RefusesCoefficientsAndIrradianceThatOverflowTheFloatTables) {
  expectRejected(kMinimal + "[rayleigh]\nscattering = [3e38]\ndensity = []\n",
                 {"rayleigh.scattering[0] = 3e+38", "optical depth along the longest ray"});
  expectRejected(kMinimal + "[absorption]\nextinction = [1e16]\ndensity = []\n", {"absorption.extinction[0] = 1e+16"});
  expectRejected(edited("irradiance = [1.8]", "irradiance = [3e38]"), {"sun.irradiance[0] = 3e+38", "<= 1e+15"});
  expectRejected(edited("irradiance = [1.8]", "irradiance = [1e15]\nangular_radius_rad = 1e-20"),
                 {"sun.angular_radius_rad = 1e-20", "use 0 for a point sun"});
  // Earth's numbers and a point sun are far inside.
  EXPECT_NO_THROW(parseConfig(edited("irradiance = [1.8]", "irradiance = [1e15]"), "test.toml"));
  EXPECT_NO_THROW(parseConfig(kMinimal + "[rayleigh]\nscattering = [1e12]\ndensity = []\n", "test.toml"));
}

// Two channels of one wavelength would share one channel of the file (the
// first came out as radiance 0): refused.
TEST(Config, RefusesRepeatedWavelengths) {
  BakeConfig c = builtinEarthConfig();
  c.atmosphere.wavelengths_nm = {680.0, 680.0, 440.0};
  try {
    validateConfig(c, "earth.toml");
    FAIL() << "accepted repeated wavelengths";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("channels.wavelengths_nm[1] = 680: repeats channels.wavelengths_nm[0]"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace skybake
