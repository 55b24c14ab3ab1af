#include "baker/bake/bake_policy.h"

#include "data_formats/texture_mapping.h"

namespace skybake {

namespace {

// A narrowed sun axis has to be this many texels' worth finer than the whole
// axis to be used. Its texels fall between the iteration's, so the stored
// scattering density, interpolated from the iteration's table there, is
// interpolated twice in the sun angle at each lookup: the flight scene's sun
// range, 0 to 100 deg, narrows the axis by 0.3 % (a tenth of a texel) and
// took the twilight rays toward the ground from 1.22 to 1.47 % RMS at 550 nm
// and those to a point from 0.69 to 1.03 % (built-in Earth, sky views only,
// 12 x 64 x 32 x 8, 524288 reference paths; docs/LEAVE_OUT.md).
constexpr double kSunAxisNarrowingMinTexels = 1.0;

bool sunRangeNarrowsAxis(const BakeConfig& config) {
  const AtmosphereDomain d = AtmosphereDomain::fromConfig(config);
  const double span = d.scattering_mu_s_coord_max - d.scattering_mu_s_coord_min;
  if (span <= 0.0) return true;  // a single sun angle
  // Same texel spacing over the whole axis would take (size - 1) / span + 1 texels.
  const double added_texels = (config.sizes.scattering_mu_s - 1) * (1.0 / span - 1.0);
  return added_texels >= kSunAxisNarrowingMinTexels;
}

}  // namespace

BakeConfig settledBakeConfig(BakeConfig config) {
  SceneRanges& scene = config.scene_ranges;
  if (scene.sun_zenith_deg && !sunRangeNarrowsAxis(config)) scene.sun_zenith_deg.reset();
  if (AtmosphereDomain::fromConfig(config).narrowed() && !config.sizes.iteration) {
    const TextureSizes defaults{};
    const int mu_s = scene.sun_zenith_deg ? defaults.scattering_mu_s
                                          : std::max(defaults.scattering_mu_s, config.sizes.scattering_mu_s);
    config.sizes.iteration =
        std::array<int, 4>{defaults.scattering_r, defaults.scattering_mu, mu_s, defaults.scattering_nu};
  }
  return config;
}

TextureSizes iterationTextureSizes(const BakeConfig& config) {
  TextureSizes sizes = config.sizes;
  if (!AtmosphereDomain::fromConfig(config).narrowed()) return sizes;
  const TextureSizes defaults{};
  const std::array<int, 4> iteration = config.sizes.iteration.value_or(std::array<int, 4>{
      defaults.scattering_r, defaults.scattering_mu, defaults.scattering_mu_s, defaults.scattering_nu});
  sizes.scattering_r = iteration[0];
  sizes.scattering_mu = iteration[1];
  sizes.scattering_mu_s = iteration[2];
  sizes.scattering_nu = iteration[3];
  return sizes;
}

}  // namespace skybake
