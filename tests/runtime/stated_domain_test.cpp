// The file states the domain its tables cover, and lookups follow it: a file
// whose stated ranges differ from what the config it carries would give
// today (a forged file here; an older bake made with other margins in
// practice) is looked up where its texels really are.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "baker/bake/bake.h"
#include "runtime/sky.h"
#include "test_configs.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

// A texel's value comes back from a lookup at its own centre up to the
// rounding of the coordinate maps (~1e-12 of a texel, see
// texture_mapping_test): far below 1e-5 relative. A lookup one texel off
// differs by far more (neighbouring texels of these tables differ by
// percent).
constexpr float kTexelTolerance = 1e-5f;
// What a neighbouring texel along the sun axis can add through that
// rounding: 1e-12 of a texel, with a hundredfold margin. A lookup one texel
// off reads the neighbour itself, ten orders of magnitude more.
constexpr float kRoundingShare = 1e-10f;

TEST(StatedDomain, LookupsFollowTheDomainTheFileStates) {
  SilentProgress silent;
  BakeOutput bake = bakeAtmosphere(test::smallEarth(2), 0, silent);
  // The carried config asks for the whole domain; the attributes say the 4D
  // tables cover only the lower half of rho and the middle of the sun axis.
  AtmosphereDomain& d = bake.file.contents.domain;
  ASSERT_FALSE(d.narrowed());
  d.scattering_rho_max_m = 0.5 * d.horizonToTopDistance();
  d.scattering_mu_s_coord_min = 0.25;
  d.scattering_mu_s_coord_max = 0.75;
  const fs::path path = fs::temp_directory_path() / ("skybake_stated_domain_" + std::to_string(getpid()) + ".exr");
  writeBakeFile(path, bake.file);
  const Sky sky = Sky::load(path);
  fs::remove(path);

  EXPECT_EQ(sky.contents().domain, d);
  const BakedRanges& ranges = sky.bakedRanges();
  const double top_of_range_m = d.radiusAtDistanceToHorizon(d.scattering_rho_max_m) - d.bottom_radius_m;
  EXPECT_NEAR(ranges.altitude_max_m, top_of_range_m, 1e-6);
  EXPECT_FALSE(ranges.containsAltitude(top_of_range_m + 100.0));
  EXPECT_NEAR(ranges.sun_zenith_min_deg, degreesFromRadians(std::acos(muSFromUnitCoord(d, 0.75))), 1e-9);
  EXPECT_NEAR(ranges.sun_zenith_max_deg, degreesFromRadians(std::acos(muSFromUnitCoord(d, 0.25))), 1e-9);

  // Every texel's centre, under the stated domain, reads that texel back.
  const Texture4D& table = sky.tables().multiple_scattering;
  const ScatteringSizes& s = sky.sampler().scatteringSizes();
  int checked = 0;
  for (int i_r = 0; i_r < s.r; ++i_r) {
    for (int i_mu_s = 0; i_mu_s < s.mu_s; ++i_mu_s) {
      const int i_mu = s.mu / 2 + 3, i_nu = s.nu / 2;  // a sky ray, nu = 1/3 at 4 slices
      const ScatteringTexelConfig c = scatteringTexelConfig(d, s, i_r, i_mu, i_mu_s, i_nu);
      if (c.nu != nuOfScatteringSlice(i_nu, s.nu)) continue;  // clamped: not at the slice's own nu
      const Spectrum looked_up = sky.sampler().scattering(table, c.r, c.mu, c.mu_s, c.nu, c.ray_intersects_ground);
      const Spectrum texel = table.at(i_r, i_mu, i_mu_s, i_nu);
      for (int ch = 0; ch < 3; ++ch) {
        // Blending with a neighbour at a coordinate off by its rounding adds
        // that rounding times the neighbour, which at the lowest sun can be
        // 1e7 times the texel itself.
        const float largest_neighbour =
            std::max(std::abs(table.at(i_r, i_mu, std::min(i_mu_s + 1, s.mu_s - 1), i_nu)[ch]),
                     std::abs(table.at(i_r, i_mu, std::max(i_mu_s - 1, 0), i_nu)[ch]));
        EXPECT_NEAR(looked_up[ch], texel[ch], kTexelTolerance * texel[ch] + kRoundingShare * largest_neighbour)
            << i_r << " " << i_mu_s << " " << ch;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, s.r * s.mu_s / 2);
}

}  // namespace
}  // namespace skybake
