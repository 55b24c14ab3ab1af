// Spectral config forms (CONFIG.md, "Spectra"): wavelength ranges, spectra
// from CSV files and inline tables resampled to the bake's wavelengths, the
// power laws, cross-sections times a number density, and the refusals.
// Resolved values are floats (Spectrum), so comparisons of computed values
// allow 1e-6 relative: float's rounding (6e-8) with room for pow's last
// bits, far below any formula error (a wrong exponent or interpolation
// weight is off by percent).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "data_formats/config/config.h"
#include "data_formats/error.h"
#include "data_formats/spectra/spectral_samples.h"
#include "data_formats/spectra/spectrum_csv.h"
#include "expect_config_rejected.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

// float rounding of a resolved value, with room for pow's last bits.
constexpr double kFloatRelativeTolerance = 1e-6;

class SpectralConfig : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("skybake_spectral_config_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& name, const std::string& text) const { std::ofstream(dir_ / name) << text; }

  // A one-constituent config: `channels` is the wavelengths' TOML value,
  // `irradiance` sun.irradiance's, `extra` further tables.
  static std::string config(const std::string& channels, const std::string& irradiance, const std::string& extra = "") {
    return "[channels]\nwavelengths_nm = " + channels +
           "\n[planet]\nbottom_radius_m = 6360000.0\ntop_radius_m = 6420000.0\n[sun]\nirradiance = " + irradiance +
           "\n" + extra;
  }

  BakeConfig parse(const std::string& text) const { return parseConfig(text, "test.toml", dir_); }

  void expectRejected(const std::string& text, std::initializer_list<std::string> fragments) const {
    test::expectConfigRejected(text, fragments, dir_);
  }

  fs::path dir_;
};

TEST_F(SpectralConfig, RangeIsEvenlySpacedWithBothEnds) {
  const BakeConfig c = parse(config("{ min_nm = 400, max_nm = 700, count = 4 }", "[1, 1, 1, 1]"));
  EXPECT_EQ(c.atmosphere.wavelengths_nm, (std::vector<double>{400.0, 500.0, 600.0, 700.0}));
  const BakeConfig three = parse(config("{ min_nm = 440, max_nm = 680, count = 3 }", "[1, 1, 1]"));
  EXPECT_EQ(three.atmosphere.wavelengths_nm, (std::vector<double>{440.0, 560.0, 680.0}));
  // The last wavelength is the given end exactly, whatever the rounding.
  const std::vector<double> w = evenlySpacedWavelengths(380.1, 779.7, 3);
  EXPECT_EQ(w.front(), 380.1);
  EXPECT_EQ(w.back(), 779.7);
}

TEST_F(SpectralConfig, MoreWavelengthsThanOneFileHoldsAreRefused) {
  expectRejected(config("{ min_nm = 380, max_nm = 780, count = 16 }", "[1]"),
                 {"channels.wavelengths_nm", "16 wavelengths", "at most 4", "channels.store = \"spectral\"",
                  "channels.store = \"cie_xyz\""});
  expectRejected(config("[400, 450, 500, 550, 600]", "[1, 1, 1, 1, 1]"),
                 {"channels.wavelengths_nm", "5 wavelengths", "at most 4"});
  expectRejected(config("{ min_nm = 380, max_nm = 780, count = 1 }", "[1]"), {"channels.wavelengths_nm.count"});
  // Refused before a billion wavelengths are made.
  expectRejected(config("{ min_nm = 380, max_nm = 780, count = 1000000000 }", "[1]"),
                 {"channels.wavelengths_nm", "1000000000 wavelengths", "at most 4"});
  expectRejected(config("{ min_nm = 780, max_nm = 380, count = 3 }", "[1, 1, 1]"), {"min_nm < max_nm"});
  expectRejected(config("{ min_nm = 380, max_nm = 780, count = 3, step = 1 }", "[1, 1, 1]"),
                 {"channels.wavelengths_nm.step", "unknown key"});
}

TEST_F(SpectralConfig, RayleighLambdaToTheMinusFour) {
  // 13.558e-6 m^-1 at 550 nm: at 440 nm times (550/440)^4 = 2.44140625.
  const BakeConfig c = parse(config("[440, 550, 680]", "[1, 1, 1]",
                                    "[rayleigh]\nscattering = { at_nm = 550, value = 13.558e-6 }\n"
                                    "density = [{ exp_term = 1.0, exp_scale = -1.25e-4 }]\n"));
  EXPECT_NEAR(c.atmosphere.rayleigh_scattering[0], 33.1005859375e-6, 33.1e-6 * kFloatRelativeTolerance);
  EXPECT_FLOAT_EQ(c.atmosphere.rayleigh_scattering[1], 13.558e-6f);
  // (550/680)^4 = 0.42797...: 5.80244e-6, the built-in Earth's 5.802e-6.
  EXPECT_NEAR(c.atmosphere.rayleigh_scattering[2], 5.802441e-6, 5.8e-6 * kFloatRelativeTolerance);
  const BakeConfig other = parse(config("[440]", "[1]",
                                        "[rayleigh]\nscattering = { at_nm = 550, value = 1e-5, exponent = 2 }\n"
                                        "density = []\n"));
  EXPECT_NEAR(other.atmosphere.rayleigh_scattering[0], 1.5625e-5, 1.5625e-5 * kFloatRelativeTolerance);
}

TEST_F(SpectralConfig, MieAngstromExponent) {
  // 4e-6 m^-1 at 550 nm, Angstrom exponent 1.3: (550/440)^1.3 = 1.3365432,
  // (550/680)^1.3 = 0.7589443.
  const BakeConfig c = parse(config("[440, 680]", "[1, 1]",
                                    "[mie]\nscattering = { at_nm = 550, value = 4e-6, angstrom_exponent = 1.3 }\n"
                                    "extinction = { at_nm = 550, value = 5e-6, angstrom_exponent = 1.3 }\n"
                                    "phase_g = 0.8\ndensity = []\n"));
  EXPECT_NEAR(c.atmosphere.mie_scattering[0], 5.346173e-6, 5.3e-6 * kFloatRelativeTolerance);
  EXPECT_NEAR(c.atmosphere.mie_scattering[1], 3.035777e-6, 3.0e-6 * kFloatRelativeTolerance);
  EXPECT_NEAR(c.atmosphere.mie_extinction[0], 5.0 / 4.0 * 5.346173e-6, 6.7e-6 * kFloatRelativeTolerance);
  // The exponent is required: no aerosol has a default one.
  expectRejected(
      config("[440]", "[1]", "[mie]\nscattering = { at_nm = 550, value = 4e-6 }\nphase_g = 0.8\ndensity = []\n"),
      {"mie.scattering.angstrom_exponent", "missing required key"});
  // The Rayleigh form is not an aerosol's.
  expectRejected(config("[440]", "[1]",
                        "[mie]\nscattering = { at_nm = 550, value = 4e-6, exponent = 4 }\nphase_g = 0.8\n"
                        "density = []\n"),
                 {"mie.scattering.exponent", "unknown key"});
}

TEST_F(SpectralConfig, CsvIsExactAtSamplesAndLinearBetween) {
  // A spreadsheet's byte-order mark, a comment, a header, CRLF and blanks.
  write("sun.csv", "\xEF\xBB\xBF# a test spectrum\nwavelength_nm,irradiance\n400,1.0\n500,3.0\r\n 600 , 2.0 \n");
  const BakeConfig c = parse(config("[400, 450, 500, 575]", "{ spectrum_csv = \"sun.csv\" }"));
  EXPECT_EQ(c.atmosphere.sun_irradiance[0], 1.0f);  // at a sample: the sample itself
  EXPECT_EQ(c.atmosphere.sun_irradiance[2], 3.0f);
  EXPECT_FLOAT_EQ(c.atmosphere.sun_irradiance[1], 2.0f);   // halfway from 1 to 3
  EXPECT_FLOAT_EQ(c.atmosphere.sun_irradiance[3], 2.25f);  // three quarters from 3 to 2
  // A band of 20 nm around 500 nm: the mean of the straight lines 2.8 -> 3
  // (490 to 500 nm) and 3 -> 2.9 (500 to 510 nm) is (29 + 29.5) / 20.
  const BakeConfig band = parse(config("[500]", "{ spectrum_csv = \"sun.csv\", band_nm = 20 }"));
  EXPECT_FLOAT_EQ(band.atmosphere.sun_irradiance[0], 2.925f);
  // The inline form reads the same way.
  const BakeConfig inline_form =
      parse(config("[400, 450, 500, 575]", "{ wavelengths_nm = [400, 500, 600], values = [1.0, 3.0, 2.0] }"));
  EXPECT_EQ(inline_form.atmosphere.sun_irradiance, c.atmosphere.sun_irradiance);
}

TEST_F(SpectralConfig, BandMeanIsTheIntegralOfTheLines) {
  const TabulatedSpectrum s{{400.0, 500.0, 600.0}, {1.0, 3.0, 2.0}};
  EXPECT_DOUBLE_EQ(s.bandMean(400.0, 600.0), (200.0 + 250.0) / 200.0);
  EXPECT_DOUBLE_EQ(s.bandMean(410.0, 420.0), 1.3);  // inside one piece: the value at the middle
}

TEST_F(SpectralConfig, CrossSectionTimesNumberDensity) {
  // Ozone's cross-sections at the built-in Earth's wavelengths (m^2) times
  // its peak number density, 5.374e18 m^-3.
  write("ozone.csv", "wavelength_nm,cross_section_m2\n440,1.582e-26\n550,3.5e-25\n680,1.209e-25\n");
  const BakeConfig c =
      parse(config("[680, 550, 440]", "[1, 1, 1]",
                   "[absorption]\nextinction = { cross_section_csv = \"ozone.csv\", number_density_m3 = 5.374e18 }\n"
                   "density = []\n"));
  EXPECT_NEAR(c.atmosphere.absorption_extinction[0], 1.209e-25 * 5.374e18, 6.5e-7 * kFloatRelativeTolerance);
  EXPECT_NEAR(c.atmosphere.absorption_extinction[1], 3.5e-25 * 5.374e18, 1.9e-6 * kFloatRelativeTolerance);
  EXPECT_NEAR(c.atmosphere.absorption_extinction[2], 1.582e-26 * 5.374e18, 8.5e-8 * kFloatRelativeTolerance);
  // Only absorption takes a cross-section.
  expectRejected(config("[440]", "{ cross_section_csv = \"ozone.csv\", number_density_m3 = 1 }"),
                 {"sun.irradiance", "must be"});
  expectRejected(config("[440]", "[1]",
                        "[absorption]\nextinction = { cross_section_csv = \"ozone.csv\", number_density_m3 = -1 }\n"
                        "density = []\n"),
                 {"absorption.extinction.number_density_m3", "must be >= 0"});
}

TEST_F(SpectralConfig, BadSpectrumFilesAreRefusedWithFileLineAndKey) {
  write("unsorted.csv", "400,1\n500,2\n450,3\n");
  expectRejected(config("[450]", "{ spectrum_csv = \"unsorted.csv\" }"),
                 {"sun.irradiance.spectrum_csv", "unsorted.csv:3", "450", "is below line 2", "must increase"});
  write("duplicate.csv", "400,1\n# comment\n400,2\n");
  expectRejected(config("[400]", "{ spectrum_csv = \"duplicate.csv\" }"),
                 {"sun.irradiance.spectrum_csv", "duplicate.csv:3", "repeats line 1"});
  write("nan.csv", "400,1\n500,nan\n");
  expectRejected(config("[450]", "{ spectrum_csv = \"nan.csv\" }"), {"nan.csv:2", "value nan", "finite"});
  write("inf_wavelength.csv", "400,1\ninf,2\n");
  expectRejected(config("[450]", "{ spectrum_csv = \"inf_wavelength.csv\" }"),
                 {"inf_wavelength.csv:2", "wavelength inf"});
  write("columns.csv", "400,1,2\n");
  expectRejected(config("[450]", "{ spectrum_csv = \"columns.csv\" }"), {"columns.csv:1", "two columns"});
  write("one.csv", "400,1\n");
  expectRejected(config("[400]", "{ spectrum_csv = \"one.csv\" }"), {"one.csv", "1 samples", "at least 2"});
  write("range.csv", "400,1\n500,2\n");
  expectRejected(config("[390]", "{ spectrum_csv = \"range.csv\" }"),
                 {"sun.irradiance", "range.csv", "channels.wavelengths_nm[0] = 390", "outside", "400 to 500"});
  expectRejected(config("[495]", "{ spectrum_csv = \"range.csv\", band_nm = 20 }"),
                 {"sun.irradiance", "range.csv", "485 to 505", "outside"});
  expectRejected(config("[450]", "{ spectrum_csv = \"missing.csv\" }"),
                 {"sun.irradiance.spectrum_csv", "missing.csv", "no such spectrum file"});
  expectRejected(config("[450]", "{ spectrum_csv = \".\" }"),
                 {"sun.irradiance.spectrum_csv", "is a directory, not a spectrum file"});
  // Inline spectra follow the same rules.
  expectRejected(config("[450]", "{ wavelengths_nm = [500, 400], values = [1, 2] }"),
                 {"sun.irradiance.wavelengths_nm[1]", "must increase"});
  expectRejected(config("[450]", "{ wavelengths_nm = [400, 500], values = [1] }"),
                 {"sun.irradiance.values", "needs 2 values"});
  expectRejected(config("[450]", "{ wavelengths_nm = [400, 500], values = [1, nan] }"),
                 {"sun.irradiance.values[1]", "finite"});
  expectRejected(config("[450]", "{ value = 1 }"), {"sun.irradiance", "must be a list of one number per wavelength"});
}

TEST_F(SpectralConfig, CanonicalTomlHoldsTheResolvedValues) {
  write("sun.csv", "400,1.0\n500,3.0\n600,2.0\n");
  const BakeConfig c = parse(config("{ min_nm = 400, max_nm = 600, count = 3 }", "{ spectrum_csv = \"sun.csv\" }"));
  const std::string canonical = configToToml(c);
  EXPECT_EQ(canonical.find("sun.csv"), std::string::npos) << canonical;
  EXPECT_NE(canonical.find("wavelengths_nm = [400.0, 500.0, 600.0]"), std::string::npos) << canonical;
  EXPECT_NE(canonical.find("irradiance = [1.0, 3.0, 2.0]"), std::string::npos) << canonical;
  // It reads back without the file.
  fs::remove(dir_ / "sun.csv");
  EXPECT_EQ(parseConfig(canonical, "canonical.toml").atmosphere, c.atmosphere);
}

TEST_F(SpectralConfig, SpectrumFilesAreRelativeToTheConfigFile) {
  fs::create_directories(dir_ / "configs" / "spectra");
  write("configs/spectra/sun.csv", "400,1.0\n600,2.0\n");
  write("configs/planet.toml", config("[500]", "{ spectrum_csv = \"spectra/sun.csv\" }"));
  EXPECT_FLOAT_EQ(loadConfigFile(dir_ / "configs" / "planet.toml").atmosphere.sun_irradiance[0], 1.5f);
}

// The shipped spectra read, cover the visible, and hold what their headers
// say: the built-in Earth's sun.irradiance is the mean of the ASTM G173
// extraterrestrial samples from each wavelength to 10 nm above it (how its
// values were made), which a mistyped sample in those bands would break;
// the cross-section gives the built-in Earth's ozone (made from 233 K
// data, 10 nm means) within 7 %: about 5, 1 and 4 % apart at 440, 550 and
// 680 nm, where the Chappuis band's weak edges change by that much from
// 233 K to 293 K; a misread exponent or a shifted row would be off by far
// more.
TEST_F(SpectralConfig, ShippedSpectraMatchTheBuiltInEarth) {
  const fs::path presets = fs::path(SKYBAKE_SOURCE_DIR) / "data_formats" / "presets";
  const TabulatedSpectrum sun = readSpectrumCsv(presets / "solar_irradiance_astm_e490.csv");
  EXPECT_LE(sun.firstWavelength_nm(), 360.0);
  EXPECT_GE(sun.lastWavelength_nm(), 830.0);
  const TabulatedSpectrum ozone = readSpectrumCsv(presets / "ozone_cross_section_serdyuchenko_293k.csv");
  EXPECT_LE(ozone.firstWavelength_nm(), 380.0);
  EXPECT_GE(ozone.lastWavelength_nm(), 780.0);
  const AtmosphereParameters earth = builtinEarthConfig().atmosphere;
  constexpr double kEarthOzoneNumberDensity_m3 = 5.374e18;
  for (int c = 0; c < earth.channelCount(); ++c) {
    const double lambda = earth.wavelengths_nm[static_cast<size_t>(c)];
    double sum = 0.0;
    int samples = 0;
    for (size_t i = 0; i < sun.wavelengths_nm.size(); ++i) {
      if (sun.wavelengths_nm[i] >= lambda && sun.wavelengths_nm[i] < lambda + 10.0) sum += sun.values[i], ++samples;
    }
    // The preset's numbers have 5 or 6 digits.
    EXPECT_NEAR(sum / samples, earth.sun_irradiance[c], 1e-5 * earth.sun_irradiance[c]) << lambda << " nm";
    EXPECT_NEAR(ozone.bandMean(lambda, lambda + 10.0) * kEarthOzoneNumberDensity_m3, earth.absorption_extinction[c],
                0.07 * earth.absorption_extinction[c])
        << lambda << " nm";
  }
  // The spectral preset resolves them.
  const BakeConfig spectral = loadConfigFile(presets / "earth_spectral.toml");
  EXPECT_EQ(spectral.atmosphere.wavelengths_nm, (std::vector<double>{440.0, 520.0, 600.0, 680.0}));
  EXPECT_NEAR(spectral.atmosphere.rayleigh_scattering[3], 5.802e-6, 1e-3 * 5.802e-6);
}

}  // namespace
}  // namespace skybake
