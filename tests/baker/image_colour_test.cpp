// Pixels to colour (image_colour.h): luminance in cd m^-2 for an EXR, and
// the preview scale that keeps --exposure a multiplier on spectral
// radiance; the display encoding's sRGB transfer function.
#include <gtest/gtest.h>

#include "baker/render/image_colour.h"
#include "runtime/colour/luminance.h"
#include "runtime/colour/spectral_to_xyz.h"

namespace skybake {
namespace {

double luminanceOf(const std::vector<float>& rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

TEST(ImageColour, ExrIsLuminanceAndPreviewKeepsExposure) {
  const std::vector<double> wavelengths = {680.0, 550.0, 440.0};
  const SpectralImage flat{1, 1, 3, {0.1f, 0.1f, 0.1f}};  // W m^-2 sr^-1 nm^-1
  // 683 lm/W times the integral of ybar times the radiance. The luminance
  // weights are printed to four decimals (5e-5 relative).
  const double luminance = colour::kMaxLuminousEfficacy_lm_per_W * colour::ybarIntegral_nm() * 0.1;
  EXPECT_NEAR(luminanceOf(linearSrgbImage(flat, wavelengths, colour::kMaxLuminousEfficacy_lm_per_W)), luminance,
              1e-4 * luminance);
  // The preview: a flat spectrum of 1 / exposure has Y = 1 after exposure.
  const double exposure = 10.0;
  const double y = exposure * luminanceOf(linearSrgbImage(flat, wavelengths, previewScalePerExposure()));
  EXPECT_NEAR(y, 1.0, 1e-4);
}

TEST(ImageColour, DisplayEncodingIsSrgb) {
  // Linear 0.18 (mid grey) encodes to 118 of 255; 0 and 1 to the ends;
  // beyond 1 clips.
  const std::vector<unsigned char> bytes = encodeForDisplay({0.0f, 0.18f, 1.0f, 4.0f}, 1.0, ToneMap::None);
  EXPECT_EQ(bytes, (std::vector<unsigned char>{0, 118, 255, 255}));
}

// A component outside the sRGB gamut (negative: the deepest blue of a clear
// sky can make red negative) shows as 0 under every tone map. The tone
// curves' formulas alone turn some negatives positive: ACES's rational fit
// gives 0.21 at -0.1, Reinhard's v / (1 + v) gives 2 at -2.
TEST(ImageColour, NegativeComponentsShowAsBlack) {
  for (const ToneMap tone_map : {ToneMap::None, ToneMap::Reinhard, ToneMap::Aces}) {
    const std::vector<unsigned char> bytes = encodeForDisplay({-0.1f, -2.0f, -1.0f}, 1.0, tone_map);
    EXPECT_EQ(bytes, (std::vector<unsigned char>{0, 0, 0})) << static_cast<int>(tone_map);
  }
  // The tone maps themselves at 1: Reinhard 0.5, sRGB-encoded 188 of 255;
  // ACES 0.804, encoded 232.
  EXPECT_EQ(encodeForDisplay({1.0f}, 1.0, ToneMap::Reinhard), std::vector<unsigned char>{188});
  EXPECT_EQ(encodeForDisplay({1.0f}, 1.0, ToneMap::Aces), std::vector<unsigned char>{232});
}

}  // namespace
}  // namespace skybake
