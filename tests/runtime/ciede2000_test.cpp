// CIEDE2000 against the test pairs Sharma, Wu and Dalal published with their
// implementation notes (Color Res. Appl. 30(1), 2005, table 1), and CIELAB
// against its definition at the white and at mid grey.
#include <gtest/gtest.h>

#include <array>

#include "runtime/colour/ciede2000.h"
#include "runtime/colour/cielab.h"

namespace skybake::colour {
namespace {

struct TestPair {
  Lab first, second;
  double delta_e;  // as published, 4 decimals
};

// Pairs 1, 4, 7, 9-15 (the hue angle's wrap-around at 0 / 360 deg and the
// mean hue's choice of side), 16-21 (large differences and the lightness
// weight), 25 and 34 (the rotation term near blue, h' ~ 275 deg).
constexpr std::array<TestPair, 19> kSharmaPairs = {{
    {{50.0, 2.6772, -79.7751}, {50.0, 0.0, -82.7485}, 2.0425},
    {{50.0, -1.3802, -84.2814}, {50.0, 0.0, -82.7485}, 1.0000},
    {{50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}, 2.3669},
    {{50.0, 2.4900, -0.0010}, {50.0, -2.4900, 0.0009}, 7.1792},
    {{50.0, 2.4900, -0.0010}, {50.0, -2.4900, 0.0010}, 7.1792},
    {{50.0, 2.4900, -0.0010}, {50.0, -2.4900, 0.0011}, 7.2195},
    {{50.0, 2.4900, -0.0010}, {50.0, -2.4900, 0.0012}, 7.2195},
    {{50.0, -0.0010, 2.4900}, {50.0, 0.0009, -2.4900}, 4.8045},
    {{50.0, -0.0010, 2.4900}, {50.0, 0.0010, -2.4900}, 4.8045},
    {{50.0, -0.0010, 2.4900}, {50.0, 0.0011, -2.4900}, 4.7461},
    {{50.0, 2.5, 0.0}, {50.0, 0.0, -2.5}, 4.3065},
    {{50.0, 2.5, 0.0}, {73.0, 25.0, -18.0}, 27.1492},
    {{50.0, 2.5, 0.0}, {61.0, -5.0, 29.0}, 22.8977},
    {{50.0, 2.5, 0.0}, {56.0, -27.0, -3.0}, 31.9030},
    {{50.0, 2.5, 0.0}, {58.0, 24.0, 15.0}, 19.4535},
    {{50.0, 2.5, 0.0}, {50.0, 3.1736, 0.5854}, 1.0000},
    {{50.0, 2.5, 0.0}, {50.0, 3.2972, 0.0}, 1.0000},
    {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
    {{22.7233, 20.0904, -46.6940}, {23.0331, 14.9730, -42.5619}, 2.0373},
}};

// The published values are rounded to 4 decimals: half a unit of the last,
// with room for the rounding of the published L*a*b* inputs themselves.
constexpr double kPublishedRounding = 0.6e-4;

TEST(Ciede2000, MatchesSharmaWuDalalTestPairs) {
  for (const TestPair& p : kSharmaPairs) {
    EXPECT_NEAR(ciede2000(p.first, p.second), p.delta_e, kPublishedRounding)
        << p.first.l << " " << p.first.a << " " << p.first.b << " vs " << p.second.l << " " << p.second.a << " "
        << p.second.b;
    // The formula is symmetric in its two colours (Sharma et al., section 3).
    EXPECT_NEAR(ciede2000(p.second, p.first), p.delta_e, kPublishedRounding);
  }
}

TEST(Ciede2000, ZeroForIdenticalColours) {
  for (const TestPair& p : kSharmaPairs) EXPECT_EQ(ciede2000(p.first, p.first), 0.0);
}

TEST(Cielab, WhiteAndGreyHaveTheirDefinedLightness) {
  const Xyz white = srgbWhiteXyz();
  const Lab w = labFromXyz(white, white);
  EXPECT_NEAR(w.l, 100.0, 1e-12);
  EXPECT_NEAR(w.a, 0.0, 1e-12);
  EXPECT_NEAR(w.b, 0.0, 1e-12);
  // L* = 50 at Y / Yn = ((50 + 16) / 116)^3 = 0.18419 (the cube-root branch).
  const double y_grey = std::pow(66.0 / 116.0, 3.0);
  const Lab g = labFromXyz({white.x * y_grey, y_grey, white.z * y_grey}, white);
  EXPECT_NEAR(g.l, 50.0, 1e-12);
  // Below (6/29)^3 the straight line: L* = 903.3 Y / Yn (CIE 015's kappa, 24389 / 27).
  const Lab dark = labFromXyz({white.x * 1e-3, 1e-3, white.z * 1e-3}, white);
  EXPECT_NEAR(dark.l, 24389.0 / 27.0 * 1e-3, 1e-12);
}

}  // namespace
}  // namespace skybake::colour
