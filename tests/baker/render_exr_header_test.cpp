// skybake render's EXR output read back with OpenImageIO: the standard
// chromaticities and whiteLuminance attributes, skybake's own header
// attributes (units, wavelengths, the sun), spectral channels on request,
// and the sun disk's light in the pixels matching the header's sun.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "baker/render/image_colour.h"
#include "data_formats/angles.h"
#include "runtime/colour/luminance.h"
#include "runtime/sky.h"

namespace skybake {
namespace {

const char* const kBake = SKYBAKE_TEST_BAKE_DIR "/earth.exr";

std::filesystem::path workDir() {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("skybake_render_exr_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

// Runs skybake with `arguments`; its exit status.
int runSkybake(const std::string& arguments) {
  const std::string command = std::string(SKYBAKE_BINARY) + " " + arguments + " 2>/dev/null";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Runs skybake render of the test bake with `arguments`; its exit status.
int render(const std::string& arguments) { return runSkybake(std::string("render ") + kBake + " " + arguments); }

struct ExrImage {
  OIIO::ImageSpec spec;
  std::vector<float> pixels;
};

ExrImage readExr(const std::filesystem::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  EXPECT_TRUE(in) << path;
  ExrImage image;
  if (!in) return image;
  image.spec = in->spec();
  image.pixels.resize(static_cast<size_t>(image.spec.width) * image.spec.height * image.spec.nchannels);
  EXPECT_TRUE(in->read_image(0, 0, 0, image.spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()));
  in->close();
  return image;
}

const char* const kView = "--altitude-m 0 --sun-zenith-deg 40 --projection latlong --size 128x64";

TEST(RenderExr, StatesColourSpaceUnitsAndSun) {
  const std::filesystem::path path = workDir() / "rgb.exr";
  ASSERT_EQ(render(std::string(kView) + " -o " + path.string()), 0);
  const ExrImage image = readExr(path);
  const OIIO::ImageSpec& spec = image.spec;
  ASSERT_EQ(spec.nchannels, 3);
  EXPECT_EQ(spec.channelnames, (std::vector<std::string>{"R", "G", "B"}));

  const OIIO::ParamValue* chromaticities = spec.find_attribute("chromaticities");
  ASSERT_NE(chromaticities, nullptr);
  ASSERT_EQ(chromaticities->type(), OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8));
  const float* c = static_cast<const float*>(chromaticities->data());
  // Rec. 709 / sRGB primaries and D65, stored as floats: exact to float
  // rounding of the decimal values.
  const float expected[8] = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
  for (int i = 0; i < 8; ++i) EXPECT_FLOAT_EQ(c[i], expected[i]) << i;
  EXPECT_FLOAT_EQ(spec.get_float_attribute("whiteLuminance"), 1.0f);
  EXPECT_EQ(spec.get_string_attribute("skybake:units"), "cd m^-2");
  EXPECT_EQ(spec.get_string_attribute("skybake:wavelengths_nm"), "680 550 440");
  EXPECT_EQ(spec.get_string_attribute("skybake:projection"), "latlong");
  EXPECT_EQ(spec.get_int_attribute("skybake:sun_in_image"), 1);
  EXPECT_FLOAT_EQ(spec.get_float_attribute("skybake:sun_zenith_deg"), 40.0f);

  const OIIO::ParamValue* direction = spec.find_attribute("skybake:sun_direction");
  ASSERT_NE(direction, nullptr);
  ASSERT_EQ(direction->type().aggregate, OIIO::TypeDesc::VEC3);
  const float* d = static_cast<const float*>(direction->data());
  EXPECT_NEAR(d[0], std::sin(radiansFromDegrees(40.0)), 1e-6);
  EXPECT_NEAR(d[1], 0.0, 1e-6);
  EXPECT_NEAR(d[2], std::cos(radiansFromDegrees(40.0)), 1e-6);

  // The sun's irradiance at normal incidence is the runtime's.
  const Sky sky = Sky::load(kBake);
  const glm::dvec3 sun(d[0], d[1], d[2]);
  const glm::dvec3 camera(0.0, 0.0, sky.atmosphere().bottom_radius_m);
  const Spectrum lookup = sky.sunIrradiance(camera, sun, sun);
  std::istringstream irradiance(spec.get_string_attribute("skybake:sun_irradiance_W_m2_nm"));
  for (int ch = 0; ch < 3; ++ch) {
    float value = 0.0f;
    ASSERT_TRUE(irradiance >> value);
    // Written as the float's shortest text: it reads back to the same float.
    EXPECT_EQ(value, lookup[ch]);
  }
  float extra;
  EXPECT_FALSE(irradiance >> extra);  // one value per channel
  const OIIO::ParamValue* illuminance = spec.find_attribute("skybake:sun_illuminance_rgb_lx");
  ASSERT_NE(illuminance, nullptr);
  ASSERT_EQ(illuminance->type().aggregate, OIIO::TypeDesc::VEC3);
  const float* rgb = static_cast<const float*>(illuminance->data());
  const double illuminance_lx = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
  // The sun through 1.3 air masses at 40 deg: about 100 klx at normal
  // incidence on Earth (75 to 110 klx for clear days).
  EXPECT_GT(illuminance_lx, 75e3);
  EXPECT_LT(illuminance_lx, 130e3);

  // With --no-sun the pixels lose exactly the sun: the difference,
  // integrated over solid angle, is the header's sun illuminance at normal
  // incidence (luminance times solid angle).
  const std::filesystem::path no_sun_path = workDir() / "no_sun.exr";
  ASSERT_EQ(render(std::string(kView) + " --no-sun -o " + no_sun_path.string()), 0);
  const ExrImage no_sun = readExr(no_sun_path);
  ASSERT_EQ(no_sun.pixels.size(), image.pixels.size());
  EXPECT_EQ(no_sun.spec.get_int_attribute("skybake:sun_in_image"), 0);
  EXPECT_NE(no_sun.spec.find_attribute("skybake:sun_direction"), nullptr);
  double sun_lx = 0.0;
  for (int y = 0; y < spec.height; ++y) {
    const double row_sr =
        2.0 * kPi / spec.width * (std::cos(y * kPi / spec.height) - std::cos((y + 1) * kPi / spec.height));
    for (int x = 0; x < spec.width; ++x) {
      const size_t i = (static_cast<size_t>(y) * spec.width + x) * 3;
      const double difference = 0.2126 * (image.pixels[i] - no_sun.pixels[i]) +
                                0.7152 * (image.pixels[i + 1] - no_sun.pixels[i + 1]) +
                                0.0722 * (image.pixels[i + 2] - no_sun.pixels[i + 2]);
      sun_lx += difference * row_sr;
    }
  }
  // The disk's area by subsamples (0.1 %, sun_disk_pixels.cpp) and its
  // transmittance averaged over the disk instead of at its centre (1e-4 at
  // 40 deg), plus float rounding of the sun's 1e9 cd m^-2 pixels.
  EXPECT_NEAR(sun_lx, illuminance_lx, 0.005 * illuminance_lx);
}

// A spectral bake of 6 wavelengths (two lane groups) renders every channel,
// and its sRGB image is the colour of those 6 channels.
TEST(RenderExr, SpectralBakeWritesEveryChannelAndConvertsThemAll) {
  const std::filesystem::path bake = workDir() / "many.exr";
  ASSERT_EQ(runSkybake(std::string("bake ") + SKYBAKE_SOURCE_DIR + "/tests/cli/small_earth_many.toml -o " +
                       bake.string() + " --threads 2"),
            0);
  const std::filesystem::path spectral = workDir() / "many_spectral.exr", rgb = workDir() / "many_rgb.exr";
  const std::string view = "render " + bake.string() + " " + kView;
  ASSERT_EQ(runSkybake(view + " --channels spectral -o " + spectral.string()), 0);
  ASSERT_EQ(runSkybake(view + " -o " + rgb.string()), 0);
  const ExrImage s = readExr(spectral), c = readExr(rgb);
  ASSERT_EQ(s.spec.nchannels, 6);
  std::vector<std::string> names = s.spec.channelnames;
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"400nm", "460nm", "520nm", "580nm", "640nm", "700nm"}));
  EXPECT_EQ(s.spec.get_string_attribute("skybake:wavelengths_nm"), "400 460 520 580 640 700");
  // OpenImageIO gives the channels in the file's (alphabetical) order,
  // which for these names is the wavelengths' order.
  const std::vector<double> wavelengths = {400, 460, 520, 580, 640, 700};
  const SpectralImage image{s.spec.width, s.spec.height, 6, s.pixels};
  const std::vector<float> expected = linearSrgbImage(image, wavelengths, colour::kMaxLuminousEfficacy_lm_per_W);
  ASSERT_EQ(c.pixels.size(), expected.size());
  // The same float conversion of the same float radiances: equal but for
  // rounding of the summation order, far below 1e-5 of a pixel's value.
  for (size_t i = 0; i < expected.size(); ++i) {
    ASSERT_NEAR(c.pixels[i], expected[i], 1e-5 * std::abs(expected[i]) + 1e-30) << "value " << i;
  }
  std::filesystem::remove_all(workDir());
}

TEST(RenderExr, SpectralChannelsAreTheBakesWavelengths) {
  const std::filesystem::path path = workDir() / "spectral.exr";
  ASSERT_EQ(render(std::string(kView) + " --channels spectral -o " + path.string()), 0);
  const ExrImage image = readExr(path);
  ASSERT_EQ(image.spec.nchannels, 3);
  std::vector<std::string> names = image.spec.channelnames;
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"440nm", "550nm", "680nm"}));
  EXPECT_EQ(image.spec.get_string_attribute("skybake:units"), "W m^-2 sr^-1 nm^-1");
  EXPECT_EQ(image.spec.find_attribute("chromaticities"), nullptr);
  // Spectral channels have no place in a PNG.
  EXPECT_EQ(render(std::string(kView) + " --channels spectral -o " + (workDir() / "x.png").string()), 2);
  std::filesystem::remove_all(workDir());
}

}  // namespace
}  // namespace skybake
