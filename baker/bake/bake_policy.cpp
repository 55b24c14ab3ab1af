#include "baker/bake/bake_policy.h"

#include "runtime/colour/colour_bake_weights.h"

#include <algorithm>
#include <cmath>

#include "data_formats/angles.h"
#include "data_formats/parameterization/texture_mapping.h"

namespace skybake {
namespace {

// Sun angles the 4D tables cover beyond the scene's range, on each side: a
// point that radiance to a point looks up 100 km from the camera sees the sun
// 0.9 deg higher or lower than the camera does (on Earth), and its lookup
// would clamp to the range's end.
constexpr double kSceneSunZenithMargin_deg = 1.0;

// Moves the low end of a narrowed sun axis down (to lower suns) until a texel
// sits on the horizon, mu_s = 0, where the sky changes character (sunlight
// reaching the ground turns off over the disk's half-degree): interpolating
// across it from texels on both sides smears it, by up to 5 % in the low-sun
// band when the texel spacing shifted by a tenth. Left alone when the
// horizon is outside the range or the low end would leave the whole range.
void alignTexelWithHorizon(AtmosphereDomain& d, int size_mu_s) {
  const double horizon = muSUnitCoord(d, 0.0);
  const double lo = d.scattering_mu_s_coord_min, hi = d.scattering_mu_s_coord_max;
  const int last = size_mu_s - 1;
  if (!(horizon > lo && horizon < hi) || last < 2) return;
  const int k = static_cast<int>(std::ceil((horizon - lo) / (hi - lo) * last));
  if (k >= last) return;
  const double aligned_lo = (horizon * last - k * hi) / (last - k);
  if (aligned_lo >= 0.0 && aligned_lo <= lo) d.scattering_mu_s_coord_min = aligned_lo;
}

}  // namespace

AtmosphereDomain sceneDomain(const BakeConfig& config) {
  const AtmosphereParameters& a = config.atmosphere;
  AtmosphereDomain d = AtmosphereDomain::fromParameters(a);
  const SceneRanges& scene = config.scene_ranges;
  if (scene.altitude_m) {
    // Cameras above the top are looked up where their rays enter, at the top.
    const double thickness_m = a.top_radius_m - a.bottom_radius_m;
    const double low_m = std::clamp((*scene.altitude_m)[0], 0.0, thickness_m);
    const double high_m = std::clamp((*scene.altitude_m)[1], low_m, thickness_m);
    d.scattering_rho_min_m = d.distanceToHorizon(a.bottom_radius_m + low_m);
    d.scattering_rho_max_m = d.distanceToHorizon(a.bottom_radius_m + high_m);
  }
  if (scene.sun_zenith_deg) {
    const double low_deg = std::max((*scene.sun_zenith_deg)[0] - kSceneSunZenithMargin_deg, 0.0);
    const double high_deg = std::min((*scene.sun_zenith_deg)[1] + kSceneSunZenithMargin_deg, a.sun_max_zenith_deg);
    d.scattering_mu_s_coord_max = muSUnitCoord(d, std::cos(radiansFromDegrees(low_deg)));
    d.scattering_mu_s_coord_min = muSUnitCoord(d, std::cos(radiansFromDegrees(high_deg)));
    alignTexelWithHorizon(d, config.sizes.scattering_mu_s);
  }
  d.scattering_ground_views = scene.views_below_horizon;
  return d;
}

namespace {

// A narrowed sun axis has to be this many texels' worth finer than the whole
// axis to be used. Its texels fall between the iteration's, so the stored
// scattering density, interpolated from the iteration's table there, is
// interpolated twice in the sun angle at each lookup, which costs more than
// a fraction of a texel gains (docs/LEAVE_OUT.md, docs/MEASUREMENTS.md).
constexpr double kSunAxisNarrowingMinTexels = 1.0;

bool sunRangeNarrowsAxis(const BakeConfig& config) {
  const AtmosphereDomain d = sceneDomain(config);
  const double span = d.scattering_mu_s_coord_max - d.scattering_mu_s_coord_min;
  if (span <= 0.0) return true;  // a single sun angle
  // Same texel spacing over the whole axis would take (size - 1) / span + 1 texels.
  const double added_texels = (config.sizes.scattering_mu_s - 1) * (1.0 / span - 1.0);
  return added_texels >= kSunAxisNarrowingMinTexels;
}

}  // namespace

BakeConfig settledBakeConfig(BakeConfig config) {
  if (config.atmosphere.storesCieXyz() && !config.colour_groups.empty()) {
    config.atmosphere =
        colour::ColourBakeWeights(config.colour_groups).cieXyzAtmosphere(config.atmosphere, config.colour_groups);
  }
  SceneRanges& scene = config.scene_ranges;
  if (scene.sun_zenith_deg && !sunRangeNarrowsAxis(config)) scene.sun_zenith_deg.reset();
  if (sceneDomain(config).narrowed() && !config.sizes.iteration) {
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
  if (!sceneDomain(config).narrowed()) return sizes;
  const TextureSizes defaults{};
  const std::array<int, 4> iteration = config.sizes.iteration.value_or(std::array<int, 4>{
      defaults.scattering_r, defaults.scattering_mu, defaults.scattering_mu_s, defaults.scattering_nu});
  sizes.scattering_r = iteration[0];
  sizes.scattering_mu = iteration[1];
  sizes.scattering_mu_s = iteration[2];
  sizes.scattering_nu = iteration[3];
  return sizes;
}

TextureSizes orderRadianceSizes(const TextureSizes& iteration) {
  // The smallest axes a table may have (data_formats/config/config_validate.cpp):
  // mu even and at least 4 (two rows each side of the horizon), nu at least 2.
  // Three quarters of nu, rounded up: 16 -> 12.
  constexpr int kMinMu = 4, kMinNu = 2;
  TextureSizes sizes = iteration;
  sizes.scattering_mu = std::max(kMinMu, 2 * (iteration.scattering_mu / 4));
  sizes.scattering_nu = std::max(kMinNu, (3 * iteration.scattering_nu + 3) / 4);
  return sizes;
}

TextureSizes densitySizes(const TextureSizes& iteration) {
  TextureSizes sizes = iteration;
  sizes.scattering_mu = orderRadianceSizes(iteration).scattering_mu;
  return sizes;
}

BakeContents bakeContents(const BakeConfig& settled) {
  const AtmosphereDomain scene = sceneDomain(settled);
  BakeContents contents = storedContents(settled, scene);
  // The whole domain's density is summed on densitySizes and stored so; a
  // narrowed scene computes its own on the stored texels (bake.cpp).
  if (!scene.narrowed()) contents.density_view_size = densitySizes(settled.sizes).scattering_mu;
  return contents;
}

}  // namespace skybake
