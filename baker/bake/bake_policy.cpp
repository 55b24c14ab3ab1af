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

// The smallest axes a 4D table may have (data_formats/config/config_validate.cpp):
// mu even and at least 4 (two rows each side of the horizon), the others 2.
constexpr int kMinMu = 4, kMinAxis = 2;

// A share of a texel count in sixteenths, rounded up; mu kept even.
int sixteenths(int n, int share, int minimum) { return std::max(minimum, (share * n + 15) / 16); }
int sixteenthsEven(int n, int share) { return std::max(kMinMu, 2 * ((share * n + 31) / 32)); }
constexpr int kThreeQuarters = 12;  // sixteenths

// The texels over a `share` of an axis of `whole` texels at the same
// spacing, plus `extra`: a scene's part of the axis as finely as the whole
// domain's, never more texels than the whole axis's.
int texelsOverShare(int whole, double share, int extra) {
  if (share >= 1.0) return whole;
  const int at_whole_spacing = static_cast<int>(std::ceil((whole - 1) * std::max(share, 0.0) - 1e-9)) + 1;
  return std::clamp(at_whole_spacing + extra, kMinAxis, whole);
}

// The sun texels the orders iterate on: resolution.iteration's mu_s, or the
// whole domain's (resolution.scattering's) before a scene's sizes are chosen.
int iterationSunTexels(const BakeConfig& config) {
  const std::optional<std::array<int, 4>>& iteration = config.sizes.iteration;
  return iteration && (*iteration)[2] != TextureSizes::kChosenByTheBake ? (*iteration)[2]
                                                                        : config.sizes.scattering_mu_s;
}

// The scene's sun texels given in resolution.scene, if any.
std::optional<int> givenSceneSunTexels(const BakeConfig& config) {
  const std::optional<std::array<int, 4>>& scene = config.sizes.scene;
  if (!scene || (*scene)[2] == TextureSizes::kChosenByTheBake) return std::nullopt;
  return (*scene)[2];
}

// How far from a texel of the iteration's sun axis the horizon may sit and
// still count as on it: the coordinates are computed in double, so a
// horizon on a texel lands within ~1e-15 of it; a horizon between texels is
// at least a texel's hundredth away on any axis under 1024 texels.
constexpr double kHorizonOnTexelTolerance = 1e-6;

// A narrowed sun range [lo, hi] (unit coordinates) widened to the nearest
// texels of an iteration sun axis of `n` texels outside it, and how many of
// those texels it then holds; nullopt unless one of them sits on the
// horizon. The scene's sun texels are then the iteration's own: its
// density is computed where the previous order was, and its tables sample
// the sun angle exactly where the whole bake's do, for any range (a range's
// own axis at the whole spacing with a texel moved onto the horizon lands
// there too, but only while its count rounds to the whole spacing).
struct SunTexelSpan {
  double lo, hi;
  int texels;
};
std::optional<SunTexelSpan> iterationSunTexelsCovering(const AtmosphereDomain& d, double lo, double hi, int n) {
  if (n < 2) return std::nullopt;
  const double last = n - 1;
  const double horizon = muSUnitCoord(d, 0.0) * last;
  if (std::abs(horizon - std::round(horizon)) > kHorizonOnTexelTolerance) return std::nullopt;
  const int first = std::max(0, static_cast<int>(std::floor(lo * last + kHorizonOnTexelTolerance)));
  const int final = std::min(n - 1, static_cast<int>(std::ceil(hi * last - kHorizonOnTexelTolerance)));
  if (final <= first) return std::nullopt;
  return SunTexelSpan{first / last, final / last, final - first + 1};
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
    const double hi = muSUnitCoord(d, std::cos(radiansFromDegrees(low_deg)));
    const double lo = muSUnitCoord(d, std::cos(radiansFromDegrees(high_deg)));
    const int iteration_texels = iterationSunTexels(config);
    const std::optional<int> given = givenSceneSunTexels(config);
    const std::optional<SunTexelSpan> span = iterationSunTexelsCovering(d, lo, hi, iteration_texels);
    if (span && (!given || *given == span->texels)) {
      d.scattering_mu_s_coord_min = span->lo;
      d.scattering_mu_s_coord_max = span->hi;
    } else {
      d.scattering_mu_s_coord_min = lo;
      d.scattering_mu_s_coord_max = hi;
      alignTexelWithHorizon(d, given.value_or(texelsOverShare(iteration_texels, hi - lo, 0)));
    }
  }
  d.scattering_ground_views = scene.views_below_horizon;
  return d;
}

namespace {

// A narrowed sun axis has to leave out this many texels' worth of the
// iteration's axis to be used: short of that it saves nothing, and an axis
// of a given count whose texels fell between the iteration's cost more than
// a fraction of a texel gains (docs/MEASUREMENTS.md, "Narrowing the sun
// axis").
constexpr double kSunAxisNarrowingMinTexels = 1.0;

bool sunRangeNarrowsAxis(const BakeConfig& config) {
  const AtmosphereDomain d = sceneDomain(config);
  const double span = d.scattering_mu_s_coord_max - d.scattering_mu_s_coord_min;
  if (span <= 0.0) return true;  // a single sun angle
  // The iteration's sun texels over the whole axis (the whole domain's
  // before a scene's sizes are chosen): the same spacing over the scene's
  // range would add this many.
  const double added_texels = (iterationSunTexels(config) - 1) * (1.0 / span - 1.0);
  return added_texels >= kSunAxisNarrowingMinTexels;
}

// The shares of the whole domain's view (mu) and view-sun (nu) axes a scene's
// stored tables keep, in sixteenths. A scene's cameras see its own part of
// the sky: at 11/16 of mu and 10/16 of nu the ground-level and flight
// scenes read within the reference's noise of the whole bake on their
// queries; at 12/16 of both the flight scene's file is 28 % of the whole
// bake's (docs/MEASUREMENTS.md, "Scene sizes").
constexpr int kSceneViewShare = 11;
constexpr int kSceneViewSunShare = 10;

// The lowest sun (largest zenith angle, degrees) of a scene whose stored
// tables take kSceneViewSunShare of the view-sun texels: the flight scene's
// (0 to 100 deg) was measured so. Deeper in twilight the glow toward the
// sun's azimuth needs every slice (8 of 16 left astronomical twilight 13 %
// off, data_formats/CONFIG.md), so a scene reaching there, or with no sun
// range, keeps them all.
constexpr double kSceneFewerViewSunSlicesMaxZenith_deg = 100.0;

// The stored 4D sizes of a scene, chosen from the whole domain's (the
// config's resolution.scattering) where resolution.scene leaves an axis out:
// - r and mu_s: the whole axis's own texels over the scene's part of it (the
//   altitude range widened to them by settledBakeConfig; the sun range by
//   sceneDomain);
// - mu: kSceneViewShare of the whole axis, or half of it when the scene has
//   no views below the horizon (its sky rays then keep the whole axis's
//   spacing);
// - nu: kSceneViewSunShare where the scene's suns stay within
//   kSceneFewerViewSunSlicesMaxZenith_deg, otherwise all of them.
std::array<int, 4> chosenSceneSizes(const BakeConfig& config, const AtmosphereDomain& scene) {
  const TextureSizes& whole = config.sizes;
  const double r_share = (scene.scattering_rho_max_m - scene.scattering_rho_min_m) / scene.horizonToTopDistance();
  const double mu_s_share = scene.scattering_mu_s_coord_max - scene.scattering_mu_s_coord_min;
  const std::optional<std::array<double, 2>>& sun = config.scene_ranges.sun_zenith_deg;
  const bool fewer_view_sun_slices = sun && (*sun)[1] <= kSceneFewerViewSunSlicesMaxZenith_deg;
  std::array<int, 4> sizes{
      texelsOverShare(whole.scattering_r, r_share, 0),
      scene.scattering_ground_views ? sixteenthsEven(whole.scattering_mu, kSceneViewShare)
                                    : std::max(kMinMu, 2 * (whole.scattering_mu / 4)),
      texelsOverShare(iterationSunTexels(config), mu_s_share, 0),
      fewer_view_sun_slices ? sixteenths(whole.scattering_nu, kSceneViewSunShare, kMinAxis) : whole.scattering_nu};
  if (config.sizes.scene) {
    for (int i = 0; i < 4; ++i) {
      if ((*config.sizes.scene)[i] != TextureSizes::kChosenByTheBake) sizes[i] = (*config.sizes.scene)[i];
    }
  }
  return sizes;
}

// The sun's zenith angle on the horizon: a scene whose suns all stay above
// it has no twilight.
constexpr double kHorizonZenith_deg = 90.0;

// The sizes a scene's orders iterate on over the whole domain where
// resolution.iteration leaves an axis out: three quarters of the whole
// domain's r where the scene narrows the altitudes (all of it otherwise: a
// sky dome's sky read 0.1 to 0.15 point worse by day at three quarters);
// every sun texel (at least the stored tables' when the sun axis
// stays whole, so that their sun texels are the iteration's); mu and nu
// whole, or at three quarters when every sun of the scene is above the
// horizon. An iteration sun axis without a texel on the horizon doubled
// the ground scene's low-sun error (31 of 41); three quarters of mu and nu
// put 0.1 to 0.2 point on the flight scene's twilight at 440 nm, and less
// than the reference's noise on any band by day (docs/MEASUREMENTS.md,
// "Scene sizes").
std::array<int, 4> chosenIterationSizes(const BakeConfig& config, const std::array<int, 4>& stored,
                                        bool sun_axis_narrowed) {
  const TextureSizes& whole = config.sizes;
  const int mu_s = sun_axis_narrowed ? whole.scattering_mu_s : std::max(whole.scattering_mu_s, stored[2]);
  const std::optional<std::array<double, 2>>& sun = config.scene_ranges.sun_zenith_deg;
  const bool day_only = sun && (*sun)[1] <= kHorizonZenith_deg;
  const bool altitudes_narrowed = config.scene_ranges.altitude_m.has_value();
  std::array<int, 4> sizes{
      altitudes_narrowed ? sixteenths(whole.scattering_r, kThreeQuarters, kMinAxis) : whole.scattering_r,
      day_only ? sixteenthsEven(whole.scattering_mu, kThreeQuarters) : whole.scattering_mu, mu_s,
      day_only ? sixteenths(whole.scattering_nu, kThreeQuarters, kMinAxis) : whole.scattering_nu};
  if (config.sizes.iteration) {
    for (int i = 0; i < 4; ++i) {
      if ((*config.sizes.iteration)[i] != TextureSizes::kChosenByTheBake) sizes[i] = (*config.sizes.iteration)[i];
    }
  }
  return sizes;
}

// Widens a scene's altitude range to the nearest texels outside it of the
// whole domain's r axis (`texels` over rho from 0 to H): the scene's
// altitude texels are then the whole bake's own, so that it reads as the
// whole bake does at every altitude inside (at the whole spacing but from
// the range's own ends, the ground-level scene's day ground rays read 0.06
// to 0.07 point above the whole bake at 680 and 550 nm; on its texels 0.01
// to 0.03, docs/MEASUREMENTS.md "Scene sizes").
void widenAltitudeRangeToWholeTexels(const AtmosphereParameters& a, int texels, std::array<double, 2>& range_m) {
  const AtmosphereDomain whole = AtmosphereDomain::fromParameters(a);
  const double thickness_m = a.top_radius_m - a.bottom_radius_m;
  const double spacing_m = whole.horizonToTopDistance() / std::max(texels - 1, 1);
  auto altitudeOfTexel = [&](int k) {
    const double rho = k * spacing_m;
    return std::min(std::sqrt(rho * rho + a.bottom_radius_m * a.bottom_radius_m) - a.bottom_radius_m, thickness_m);
  };
  const double rho_low = whole.distanceToHorizon(a.bottom_radius_m + std::clamp(range_m[0], 0.0, thickness_m));
  const double rho_high = whole.distanceToHorizon(a.bottom_radius_m + std::clamp(range_m[1], 0.0, thickness_m));
  const int low = std::max(0, static_cast<int>(std::floor(rho_low / spacing_m + kHorizonOnTexelTolerance)));
  const int high = std::min(texels - 1, static_cast<int>(std::ceil(rho_high / spacing_m - kHorizonOnTexelTolerance)));
  if (high <= low) return;
  range_m[0] = std::min(range_m[0], low == 0 ? 0.0 : altitudeOfTexel(low));
  // A range reaching the top (cameras in space) keeps its high end.
  if (range_m[1] < thickness_m) range_m[1] = std::max(range_m[1], altitudeOfTexel(high));
}

bool allChosen(const std::optional<std::array<int, 4>>& sizes) {
  return sizes && std::none_of(sizes->begin(), sizes->end(), [](int n) { return n == TextureSizes::kChosenByTheBake; });
}

}  // namespace

BakeConfig settledBakeConfig(BakeConfig config) {
  if (config.atmosphere.storesCieXyz() && !config.colour_groups.empty()) {
    config.atmosphere =
        colour::ColourBakeWeights(config.colour_groups).cieXyzAtmosphere(config.atmosphere, config.colour_groups);
  }
  SceneRanges& scene = config.scene_ranges;
  TextureSizes& sizes = config.sizes;
  if (scene.sun_zenith_deg && !sunRangeNarrowsAxis(config)) scene.sun_zenith_deg.reset();
  const bool altitude_texels_chosen = !sizes.scene || (*sizes.scene)[0] == TextureSizes::kChosenByTheBake;
  if (scene.altitude_m && altitude_texels_chosen) {
    widenAltitudeRangeToWholeTexels(config.atmosphere, sizes.scattering_r, *scene.altitude_m);
  }
  const AtmosphereDomain domain = sceneDomain(config);
  if (!domain.narrowed()) return config;
  const std::array<int, 4> stored = chosenSceneSizes(config, domain);
  sizes.iteration = chosenIterationSizes(config, stored, scene.sun_zenith_deg.has_value());
  sizes.scene = stored;
  sizes.scattering_r = stored[0];
  sizes.scattering_mu = stored[1];
  sizes.scattering_mu_s = stored[2];
  sizes.scattering_nu = stored[3];
  return config;
}

TextureSizes iterationTextureSizes(const BakeConfig& config) {
  TextureSizes sizes = config.sizes;
  if (!sceneDomain(config).narrowed()) return sizes;
  const std::array<int, 4> iteration =
      allChosen(config.sizes.iteration) ? *config.sizes.iteration : settledBakeConfig(config).sizes.iteration.value();
  sizes.scattering_r = iteration[0];
  sizes.scattering_mu = iteration[1];
  sizes.scattering_mu_s = iteration[2];
  sizes.scattering_nu = iteration[3];
  return sizes;
}

TextureSizes orderRadianceSizes(const TextureSizes& iteration) {
  // Three quarters of nu, rounded up: 16 -> 12.
  TextureSizes sizes = iteration;
  sizes.scattering_mu = std::max(kMinMu, 2 * (iteration.scattering_mu / 4));
  sizes.scattering_nu = sixteenths(iteration.scattering_nu, kThreeQuarters, kMinAxis);
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
  // The density is summed on densitySizes' texels and stored so, the whole
  // domain's and a narrowed scene's alike (bake.cpp).
  contents.density_view_size = densitySizes(settled.sizes).scattering_mu;
  return contents;
}

}  // namespace skybake
