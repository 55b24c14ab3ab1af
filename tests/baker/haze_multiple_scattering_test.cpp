// Multiple scattering in haze is forward-peaked; the tables must carry that
// peak between their sun-angle texels (runtime/physics/multiple_scattering_phase.h).
#include <gtest/gtest.h>

#include <cmath>

#include "baker/bake/bake.h"
#include "runtime/sky.h"
#include "test_configs.h"

namespace skybake {
namespace {

// Earth with 100 times the Mie scattering (visibility about 1 km at the
// ground), the default 6 orders (the stored shape is thinned for the orders
// after the second, which a bake of 2 orders lacks), small r and mu axes,
// `mu_s` sun-angle texels.
BakeConfig hazeConfig(int mu_s) {
  BakeConfig c = test::smallEarth(6);
  c.atmosphere.mie_scattering *= 100.0f;
  c.atmosphere.mie_extinction *= 100.0f;
  c.sizes.scattering_mu_s = mu_s;
  c.sizes.scattering_nu = 8;
  return c;
}

Spectrum groundSkyRadiance(const Sky& sky, double view_zenith_deg, double sun_zenith_deg) {
  const double r = sky.atmosphere().bottom_radius_m + 1.0;
  const double v = radiansFromDegrees(view_zenith_deg), s = radiansFromDegrees(sun_zenith_deg);
  return sky
      .skyRadiance(glm::dvec3(0.0, 0.0, r), glm::dvec3(std::sin(v), 0.0, std::cos(v)),
                   glm::dvec3(std::sin(s), 0.0, std::cos(s)))
      .radiance;
}

// The zenith and the sky 30 deg from the sun, sun at zenith angle 30 deg:
// views in the sun's vertical plane, where nu sits at the end of its range and
// a table interpolates across mu_s between texels 42 deg apart (0.74 and 1 in
// mu_s with 32 texels). Four times the mu_s texels put 3 texels in between,
// so the two bakes differ only by how well the peak is carried across. With
// multiple scattering interpolated as it is (a peak weight of 0), these two
// bakes disagree by up to 46 % (at the default sizes that bake's second
// order at the zenith was 2.3 times the reference solver's and a
// plane-parallel quadrature's, its total 35 % too bright); with the shape
// unthinned (format version 7) by up to 5.3 %, thinned by up to 4.1 %. 5 %
// fails both and leaves room for the fine bake's own interpolation error.
TEST(HazeMultipleScattering, PeakSurvivesInterpolationAcrossSunAngles) {
  SilentProgress silent;
  const Sky coarse(bakeAtmosphere(hazeConfig(32), 0, silent).file);
  const Sky fine(bakeAtmosphere(hazeConfig(128), 0, silent).file);
  for (double view_zenith_deg : {0.0, 60.0}) {
    const Spectrum a = groundSkyRadiance(coarse, view_zenith_deg, 30.0);
    const Spectrum b = groundSkyRadiance(fine, view_zenith_deg, 30.0);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(a[c], b[c], 0.05 * b[c]) << "view zenith " << view_zenith_deg << " deg, channel " << c;
    }
  }
}

}  // namespace
}  // namespace skybake
