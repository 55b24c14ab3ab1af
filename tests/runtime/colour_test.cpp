// The colour module: the CIE 1931 table against its published properties,
// the rule from spectral samples to XYZ, luminance, and the sRGB matrices
// and transfer function.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "data_formats/error.h"
#include "runtime/colour/cie1931_observer.h"
#include "runtime/colour/luminance.h"
#include "runtime/colour/spectral_to_xyz.h"
#include "runtime/colour/srgb_primaries.h"
#include "runtime/colour/srgb_transfer.h"

namespace skybake::colour {
namespace {

// CIE standard illuminant D65, relative spectral power (100 at 560 nm, here
// 1), 360 to 830 nm every 5 nm (CIE 015:2018, ISO/CIE 11664-2).
constexpr std::array<double, kCie1931SampleCount> kD65 = {
    0.466383, 0.493637, 0.520891, 0.510323, 0.499755, 0.523118, 0.546482, 0.687015, 0.827549, 0.871204, 0.91486,
    0.924589, 0.934318, 0.90057,  0.866823, 0.957736, 1.04865,  1.10936,  1.17008,  1.1741,   1.17812,  1.16336,
    1.14861,  1.15392,  1.15923,  1.12367,  1.08811,  1.09082,  1.09354,  1.08578,  1.07802,  1.06296,  1.0479,
    1.06239,  1.07689,  1.06047,  1.04405,  1.04225,  1.04046,  1.02023,  1.0,      0.981671, 0.963342, 0.960611,
    0.95788,  0.922368, 0.886856, 0.893459, 0.900062, 0.898026, 0.895991, 0.886489, 0.876987, 0.854936, 0.832886,
    0.834939, 0.836992, 0.81863,  0.800268, 0.801207, 0.802146, 0.812462, 0.822778, 0.80281,  0.782842, 0.740027,
    0.697213, 0.706652, 0.716091, 0.72979,  0.74349,  0.679765, 0.61604,  0.657448, 0.698856, 0.724863, 0.75087,
    0.693398, 0.635927, 0.550054, 0.464182, 0.566118, 0.668054, 0.650941, 0.633828, 0.638434, 0.64304,  0.618779,
    0.594519, 0.557054, 0.51959,  0.546998, 0.574406, 0.588765, 0.603125,
};

TEST(Cie1931Observer, TableIsThePublishedOne) {
  const auto& table = cie1931Observer();
  double sum_x = 0.0, sum_y = 0.0, sum_z = 0.0;
  for (int i = 0; i < kCie1931SampleCount; ++i) {
    const ColourMatchingSample& s = table[static_cast<size_t>(i)];
    EXPECT_EQ(s.wavelength_nm, 360.0 + kCie1931Step_nm * i);
    if (s.wavelength_nm >= 380.0 && s.wavelength_nm <= 780.0) sum_x += s.xbar, sum_y += s.ybar, sum_z += s.zbar;
  }
  // Values every table prints: ybar peaks at exactly 1 at 555 nm, xbar's
  // red lobe peaks at 1.0622 at 600 nm, zbar at 1.7826 at 445 nm.
  EXPECT_EQ(table[39].wavelength_nm, 555.0);
  EXPECT_EQ(table[39].ybar, 1.0);
  EXPECT_EQ(table[48].xbar, 1.0622);
  EXPECT_EQ(table[17].zbar, 1.7826);
  // CIE 015's sums of the 5 nm table over 380 to 780 nm, 21.37152,
  // 21.37133 and 21.37154, printed to five decimals: the tolerance is
  // their rounding.
  EXPECT_NEAR(sum_x, 21.37152, 1e-5);
  EXPECT_NEAR(sum_y, 21.37133, 1e-5);
  EXPECT_NEAR(sum_z, 21.37154, 1e-5);
}

TEST(SpectralToXyz, FlatSpectrumGivesTheTableSumsAndLuminance) {
  const std::vector<double> wavelengths = {680.0, 550.0, 440.0};
  const SpectralToXyz to_xyz(wavelengths);
  const std::array<float, 3> flat = {1.0f, 1.0f, 1.0f};  // W m^-2 sr^-1 nm^-1
  const Xyz xyz = to_xyz(flat);
  double sum_x = 0.0, sum_y = 0.0, sum_z = 0.0;
  for (const ColourMatchingSample& s : cie1931Observer()) sum_x += s.xbar, sum_y += s.ybar, sum_z += s.zbar;
  // Exact but for rounding: the rule holds the end samples, so a flat
  // spectrum is flat over the whole table.
  EXPECT_NEAR(xyz.x, sum_x * kCie1931Step_nm, 1e-12 * xyz.x);
  EXPECT_NEAR(xyz.y, sum_y * kCie1931Step_nm, 1e-12 * xyz.y);
  EXPECT_NEAR(xyz.z, sum_z * kCie1931Step_nm, 1e-12 * xyz.z);
  EXPECT_NEAR(ybarIntegral_nm(), sum_y * kCie1931Step_nm, 1e-12);
  // 683 lm/W times 106.857 nm times 1 W m^-2 sr^-1 nm^-1.
  EXPECT_NEAR(luminance_cd_m2(xyz.y), 683.0 * 106.857, 683.0 * 0.001);
}

TEST(SpectralToXyz, SampleOrderDoesNotMatter) {
  const std::vector<double> sorted = {440.0, 550.0, 680.0};
  const std::vector<double> shuffled = {680.0, 440.0, 550.0};
  const std::array<float, 3> sorted_samples = {0.3f, 0.2f, 0.05f};
  const std::array<float, 3> shuffled_samples = {0.05f, 0.3f, 0.2f};
  const Xyz a = SpectralToXyz(sorted)(sorted_samples);
  const Xyz b = SpectralToXyz(shuffled)(shuffled_samples);
  // The same sums in another order: rounding only.
  EXPECT_NEAR(a.x, b.x, 1e-12 * a.x);
  EXPECT_NEAR(a.y, b.y, 1e-12 * a.y);
  EXPECT_NEAR(a.z, b.z, 1e-12 * a.z);
}

TEST(SpectralToXyz, PiecewiseLinearSpectrumIsIntegratedExactly) {
  // A spectrum linear in wavelength between 440 and 680 nm and flat outside
  // is what three samples describe: the rule must give its table sum.
  auto spectrum = [](double nm) { return 0.4 - 0.001 * (std::clamp(nm, 440.0, 680.0) - 440.0); };
  Xyz expected;
  for (const ColourMatchingSample& s : cie1931Observer()) {
    expected.x += spectrum(s.wavelength_nm) * s.xbar * kCie1931Step_nm;
    expected.y += spectrum(s.wavelength_nm) * s.ybar * kCie1931Step_nm;
    expected.z += spectrum(s.wavelength_nm) * s.zbar * kCie1931Step_nm;
  }
  const std::vector<double> wavelengths = {680.0, 550.0, 440.0, 500.0};  // a fourth sample on the same line
  const std::array<float, 4> samples = {static_cast<float>(spectrum(680.0)), static_cast<float>(spectrum(550.0)),
                                        static_cast<float>(spectrum(440.0)), static_cast<float>(spectrum(500.0))};
  const Xyz xyz = SpectralToXyz(wavelengths)(samples);
  // The samples are floats: relative rounding 6e-8.
  EXPECT_NEAR(xyz.x, expected.x, 1e-6 * expected.x);
  EXPECT_NEAR(xyz.y, expected.y, 1e-6 * expected.y);
  EXPECT_NEAR(xyz.z, expected.z, 1e-6 * expected.z);
}

TEST(SpectralToXyz, D65IsSrgbWhite) {
  std::vector<double> wavelengths;
  std::vector<float> samples;
  for (int i = 0; i < kCie1931SampleCount; ++i) {
    wavelengths.push_back(cie1931Observer()[static_cast<size_t>(i)].wavelength_nm);
    samples.push_back(static_cast<float>(kD65[static_cast<size_t>(i)]));
  }
  Xyz xyz = SpectralToXyz(wavelengths)(samples);
  xyz = {xyz.x / xyz.y, 1.0, xyz.z / xyz.y};  // normalised to Y = 1
  const LinearRgb rgb = linearSrgbFromXyz(xyz);
  // The 5 nm table's D65 is at (0.31272, 0.32903); sRGB rounds its white to
  // (0.3127, 0.3290). That 3e-5 in x and y moves R, G, B by up to 3e-4.
  EXPECT_NEAR(rgb.r, 1.0, 1e-3);
  EXPECT_NEAR(rgb.g, 1.0, 1e-3);
  EXPECT_NEAR(rgb.b, 1.0, 1e-3);
}

TEST(SpectralToXyz, RefusesBadWavelengths) {
  EXPECT_THROW(SpectralToXyz(std::vector<double>{}), Error);
  EXPECT_THROW(SpectralToXyz(std::vector<double>{550.0, 550.0}), Error);
  EXPECT_THROW(SpectralToXyz(std::vector<double>{550.0, std::nan("")}), Error);
  EXPECT_THROW(SpectralToXyz(std::vector<double>{-1.0}), Error);
}

TEST(SrgbPrimaries, MatricesAreTheStandardOnes) {
  // IEC 61966-2-1's linear sRGB to XYZ matrix, printed to four decimals:
  // the derivation from the chromaticities must round to it (5e-5).
  const Matrix3 forward = {{{0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}}};
  // Its XYZ to linear sRGB matrix is the inverse of that rounded forward
  // matrix, printed to four decimals; the rounding moves the inverse's
  // entries by up to 4e-4 (3.2406 against the exact 3.24097).
  const Matrix3 inverse = {{{3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}}};
  const Matrix3& to_xyz = xyzFromLinearSrgbMatrix();
  const Matrix3& from_xyz = linearSrgbFromXyzMatrix();
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) {
      EXPECT_NEAR(to_xyz[row][column], forward[row][column], 5e-5) << row << "," << column;
      EXPECT_NEAR(from_xyz[row][column], inverse[row][column], 5e-4) << row << "," << column;
    }
  }
  // The middle row is Rec. 709's luminance weights (also printed to four
  // decimals as 0.2126, 0.7152, 0.0722) and sums to 1: white has Y = 1.
  EXPECT_NEAR(to_xyz[1][0] + to_xyz[1][1] + to_xyz[1][2], 1.0, 1e-12);
  // White: the white point's XYZ at Y = 1 is (1, 1, 1), to rounding.
  const Chromaticity w = kSrgbChromaticities.white;
  const LinearRgb white = linearSrgbFromXyz({w.x / w.y, 1.0, (1.0 - w.x - w.y) / w.y});
  EXPECT_NEAR(white.r, 1.0, 1e-12);
  EXPECT_NEAR(white.g, 1.0, 1e-12);
  EXPECT_NEAR(white.b, 1.0, 1e-12);
  const Xyz back = xyzFromLinearSrgb({0.2, 0.5, 0.7});
  const LinearRgb round_trip = linearSrgbFromXyz(back);
  EXPECT_NEAR(round_trip.r, 0.2, 1e-12);
  EXPECT_NEAR(round_trip.g, 0.5, 1e-12);
  EXPECT_NEAR(round_trip.b, 0.7, 1e-12);
}

TEST(SrgbTransfer, EndsSegmentsAndInverse) {
  EXPECT_EQ(srgbEncode(0.0), 0.0);
  EXPECT_NEAR(srgbEncode(1.0), 1.0, 1e-12);
  EXPECT_EQ(srgbEncode(-1.0), 0.0);
  EXPECT_NEAR(srgbEncode(2.0), 1.0, 1e-12);
  // The standard's two pieces meet to within its own rounding of the
  // constants (about 1e-7 in the encoded value).
  const double below = 12.92 * kSrgbLinearSegmentEnd;
  const double above = 1.055 * std::pow(kSrgbLinearSegmentEnd, 1.0 / 2.4) - 0.055;
  EXPECT_NEAR(below, above, 1e-6);
  // 18 % grey encodes to 0.4613 (118 of 255).
  EXPECT_NEAR(srgbEncode(0.18), 0.4613, 1e-4);
  for (double v : {0.0, 0.001, 0.01, 0.18, 0.5, 1.0}) EXPECT_NEAR(srgbDecode(srgbEncode(v)), v, 1e-6);
}

}  // namespace
}  // namespace skybake::colour
