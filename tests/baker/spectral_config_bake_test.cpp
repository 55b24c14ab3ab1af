// A config that gives the same numbers through the spectral forms (a
// wavelength range, an inline spectrum, a spectrum file, a cross-section
// file) bakes a byte-identical file: the forms resolve to the very floats
// the lists give, and the file's header stores those resolved values.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "baker/bake/bake.h"
#include "data_formats/config/config.h"
#include "test_configs.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

// `text` with its first line that starts with `prefix` replaced by `line`.
std::string replacedLine(std::string text, const std::string& prefix, const std::string& line) {
  const size_t newline = text.find('\n' + prefix);
  EXPECT_NE(newline, std::string::npos) << prefix;
  if (newline == std::string::npos) return text;
  const size_t at = newline + 1;
  const size_t end = text.find('\n', at);
  return text.replace(at, end - at, line);
}

std::string fileBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(SpectralConfigBake, EquivalentFormsBakeByteIdenticalFiles) {
  const fs::path dir = fs::temp_directory_path() / ("skybake_spectral_bake_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "rayleigh.csv") << "# m^-1\n400,4.0e-5\n440,3.31e-5\n560,1.3e-5\n680,5.8e-6\n700,5.0e-6\n";
  std::ofstream(dir / "ozone.csv") << "400,1e-27\n440,1.5e-26\n560,3.5e-25\n680,1.25e-25\n";

  // The built-in Earth at small sizes, on evenly spaced wavelengths, as lists.
  std::string lists = configToToml(test::smallEarth(2));
  lists = replacedLine(lists, "wavelengths_nm = ", "wavelengths_nm = [440.0, 560.0, 680.0]");
  lists = replacedLine(lists, "irradiance = ", "irradiance = [1.9, 1.8, 1.5]");
  lists = replacedLine(lists, "scattering = [", "scattering = [3.31e-5, 1.3e-5, 5.8e-6]");
  lists = replacedLine(lists, "extinction = [6", "extinction = [1.5e-26, 3.5e-25, 1.25e-25]");
  // The same numbers through the other forms (a number density of 1 m^-3
  // leaves the cross-sections as they are).
  std::string forms = lists;
  forms = replacedLine(forms, "wavelengths_nm = ", "wavelengths_nm = { min_nm = 440, max_nm = 680, count = 3 }");
  forms =
      replacedLine(forms, "irradiance = ",
                   "irradiance = { wavelengths_nm = [360, 440, 560, 680, 830], values = [1.0, 1.9, 1.8, 1.5, 1.2] }");
  forms = replacedLine(forms, "scattering = [", "scattering = { spectrum_csv = \"rayleigh.csv\" }");
  forms = replacedLine(forms, "extinction = [1",
                       "extinction = { cross_section_csv = \"ozone.csv\", number_density_m3 = 1.0 }");
  ASSERT_NE(forms, lists);

  const BakeConfig from_lists = parseConfig(lists, "lists.toml", dir);
  const BakeConfig from_forms = parseConfig(forms, "forms.toml", dir);
  ASSERT_EQ(from_forms.atmosphere, from_lists.atmosphere);
  ASSERT_EQ(configToToml(from_forms), configToToml(from_lists));

  SilentProgress silent;
  BakeOutput one = bakeAtmosphere(from_lists, 0, silent);
  BakeOutput two = bakeAtmosphere(from_forms, 0, silent);
  setStoredReport(one, false);
  setStoredReport(two, false);
  writeBakeFile(dir / "lists.exr", one.file);
  writeBakeFile(dir / "forms.exr", two.file);
  const std::string bytes = fileBytes(dir / "lists.exr");
  EXPECT_FALSE(bytes.empty());
  EXPECT_TRUE(bytes == fileBytes(dir / "forms.exr")) << "the spectral forms baked a different file";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace skybake
