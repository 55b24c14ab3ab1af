// Version 2 bake files (tests/data_formats/version2/, made with
// tiny_earth.toml there) are still read: the optical-depth part under its
// old name, the atmosphere from the config they carry, and the domain from
// the radii and sun cosines they state.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <unistd.h>

#include "data_formats/bake_file/bake_file.h"
#include "data_formats/config/config.h"
#include "runtime/sky.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

const fs::path kVersion2Dir = fs::path(SKYBAKE_SOURCE_DIR) / "tests/data_formats/version2";

TEST(BakeFileVersion2, WholeDomainFileReadsAsItsConfigSays) {
  const BakeFile bake = readBakeFile(kVersion2Dir / "tiny_whole_domain.exr");
  EXPECT_EQ(bake.format_version, 2);
  const BakeConfig config = loadConfigFile(kVersion2Dir / "tiny_earth.toml");
  EXPECT_EQ(bake.contents.atmosphere, config.atmosphere);
  EXPECT_EQ(bake.contents.sizes, config.sizes);
  EXPECT_EQ(bake.contents.outputs, config.scene);
  // The stated ends are the whole domain's to rounding, and are read as them,
  // on Bruneton's sun axis, with irradiance rows linear in altitude.
  AtmosphereDomain whole = AtmosphereDomain::fromParameters(config.atmosphere);
  whole.sun_axis = SunAxisMapping::DistanceToTop;
  whole.irradiance_rows = IrradianceRows::Linear;
  EXPECT_EQ(bake.contents.domain, whole);
  EXPECT_EQ(bake.orders_computed, 3);
  EXPECT_EQ(bake.tables.optical_depth.texels.size(), 16u * 4u);
  EXPECT_GT(bake.tables.optical_depth.at(0, 0)[2], 0.0f);
}

// The scene bake's domain (cameras 0 to 15 km, suns 0 to 90 deg widened by
// the 1 deg margin of that time, sky views only) comes from the radii and
// cosines the file states: its texel ends map back to them.
TEST(BakeFileVersion2, SceneFileDomainComesFromItsStatedRanges) {
  const BakeFile bake = readBakeFile(kVersion2Dir / "tiny_scene.exr");
  const AtmosphereDomain& d = bake.contents.domain;
  const ScatteringSizes s = ScatteringSizes::fromTextureSizes(bake.contents.sizes);
  EXPECT_TRUE(d.narrowed());
  EXPECT_FALSE(d.scattering_ground_views);
  // r comes back through sqrt(rho^2 + R^2) with R = 6.36e6 m: ~1e-9 m.
  EXPECT_NEAR(rFromScatteringTexel(d, s, 0), d.bottom_radius_m, 1e-6);
  EXPECT_NEAR(rFromScatteringTexel(d, s, s.r - 1), d.bottom_radius_m + 15000.0, 1e-6);
  EXPECT_NEAR(std::acos(muSFromScatteringTexel(d, s, s.mu_s - 1)), 0.0, 1e-6);
  // The low end: 91 deg, moved down by less than a texel to sit a texel on the horizon.
  const double lowest_deg = degreesFromRadians(std::acos(muSFromScatteringTexel(d, s, 0)));
  EXPECT_GE(lowest_deg, 91.0 - 1e-9);
  EXPECT_LT(lowest_deg, 91.0 + 90.0 / (s.mu_s - 1));

  const Sky sky(bake);
  EXPECT_NEAR(sky.bakedRanges().altitude_max_m, 15000.0, 1e-3);
  EXPECT_NEAR(sky.bakedRanges().sun_zenith_max_deg, lowest_deg, 1e-9);
}

// Written again, a version 2 bake becomes a version 4 file (the newest on
// its sun axis) that states the same contents and reads back to the same
// lookups.
TEST(BakeFileVersion2, RewrittenAsVersion3KeepsContentsAndLookups) {
  const BakeFile old_file = readBakeFile(kVersion2Dir / "tiny_scene.exr");
  const fs::path path = fs::temp_directory_path() / ("skybake_v2_rewritten_" + std::to_string(getpid()) + ".exr");
  writeBakeFile(path, old_file);
  const BakeFile new_file = readBakeFile(path);
  fs::remove(path);
  EXPECT_EQ(new_file.format_version, kFirstSplitSunAxisFormatVersion - 1);
  EXPECT_TRUE(new_file.contents == old_file.contents);
  EXPECT_EQ(new_file.tables.multiple_scattering.texels, old_file.tables.multiple_scattering.texels);
  const Sky before(old_file), after(new_file);
  const glm::dvec3 camera(0.0, 0.0, before.atmosphere().bottom_radius_m + 1000.0);
  const glm::dvec3 view = glm::normalize(glm::dvec3(0.3, 0.1, 0.5));
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.6, 0.0, 0.4));
  EXPECT_EQ(before.skyRadiance(camera, view, sun).radiance, after.skyRadiance(camera, view, sun).radiance);
}

}  // namespace
}  // namespace skybake
