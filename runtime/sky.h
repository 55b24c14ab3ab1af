// Sky: the lookup API over a bake. Positions are in metres relative to the
// planet centre, directions are unit vectors; radiance is spectral, in
// W m^-2 sr^-1 nm^-1, irradiance in W m^-2 nm^-1, one lane per channel in the
// file's channel order (unused lanes 0). All lookups are const and thread-safe.
//
// Geometry conventions:
//  - a camera in space is moved along its ray to where the ray enters the
//    atmosphere; a ray that misses the atmosphere sees radiance 0 and
//    transmittance 1;
//  - a camera below the ground is treated as on the ground, directly above
//    where it is;
//  - every sun direction is valid. Below the lowest baked sun angle
//    (sun.max_zenith_deg) single scattering is integrated along the ray for
//    the sun where it is, and what the tables give (multiple scattering, the
//    sky irradiance) is their value at that angle scaled by the night
//    continuation (runtime/physics/night_sky.h): continuous there, non-increasing as
//    the sun sinks, and 0 (kNightFloor) from the point where no sunlit air
//    is in reach of light scattered twice (121 deg for Earth) to the nadir;
//  - a bake whose [scene] narrows the altitudes and sun angles (bakedRanges)
//    looks a camera or point outside them up at the nearest baked altitude,
//    in the same direction relative to its horizon, and a sun outside them at
//    the nearest baked sun angle: close for small excursions, wrong for large
//    ones. Check bakedRanges().contains(...) where that can happen. A scene
//    whose sun range reaches sun.max_zenith_deg goes on below it as a bake
//    of the whole domain does.
//
// Where the values come from: the baked tables, except single scattering
// with the sun below the horizon, which is integrated along each view ray
// over the baked transmittance table (the tables cannot follow the edge of
// the planet's shadow; see sky_twilight.cpp). Such twilight lookups cost about six
// times a day lookup. A bake without views below the horizon ([scene]
// views_below_horizon = false) integrates rays that end on the ground
// whole, multiple scattering over the baked density (about 20 times a
// table lookup).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "data_formats/bake_file/bake_file.h"
#include "runtime/physics/atmosphere_ray.h"
#include "runtime/physics/moon_occluder.h"
#include "runtime/physics/multiple_scattering_phase.h"
#include "runtime/physics/phase_functions.h"
#include "runtime/physics/single_scattering_ray.h"
#include "runtime/tables/table_sampler.h"

namespace skybake {

// A lookup's result holds one or more per-channel values (Values): a
// Spectrum for one lane group (the lookups below), std::vector<float> for
// every channel of a bake (Sky::everyChannel). lookupParts lists them in
// order, so that code joining or storing results handles every lookup alike.
template <typename Values>
struct RadianceAndTransmittanceOf {
  Values radiance;       // W m^-2 sr^-1 nm^-1 scattered toward the camera
  Values transmittance;  // along the same path, dimensionless
};
using RadianceAndTransmittance = RadianceAndTransmittanceOf<Spectrum>;
template <typename Values>
auto lookupParts(RadianceAndTransmittanceOf<Values>& v) {
  return std::tie(v.radiance, v.transmittance);
}
inline auto lookupParts(Spectrum& v) { return std::tie(v); }
inline auto lookupParts(std::vector<float>& v) { return std::tie(v); }

// What lights a lookup: the sun and, during a solar eclipse, the moon before
// it. A sun direction alone converts to it (no moon), so a plain lookup reads
// sky.skyRadiance(camera, view_dir, sun_dir); an eclipse
// sky.skyRadiance(camera, view_dir, {sun_dir, moon}).
struct Sunlight {
  // Implicit: a direction is the uneclipsed sun.
  Sunlight(const glm::dvec3& sun_direction) : direction(sun_direction) {}  // NOLINT(google-explicit-constructor)
  Sunlight(const glm::dvec3& sun_direction, const Moon& eclipse_moon) : direction(sun_direction), moon(eclipse_moon) {}
  Sunlight(const glm::dvec3& sun_direction, const Moon& eclipse_moon, const Spectrum& skylight_at_camera)
      : direction(sun_direction), moon(eclipse_moon), camera_skylight(skylight_at_camera) {}

  glm::dvec3 direction;  // toward the sun, the same everywhere (the sun is far); any length, lookups normalise it
  Moon moon;             // radius 0: no eclipse
  // Sky::eclipseSkylight at the camera, given by a caller that looks up
  // many views from one camera in the atmosphere (an image): each lookup
  // then costs about a third as much. A camera in space enters the
  // atmosphere at another point for each view: leave it unset there. Used
  // only with a moon.
  std::optional<Spectrum> camera_skylight;
};

// The camera altitudes and sun zenith angles a bake's scattering tables
// serve: [scene] altitude_range_m and sun_zenith_range_deg (with their 1 deg
// margin), or the whole atmosphere (altitude_max_m infinite: cameras in
// space are looked up where their rays enter) and every sun (0 to 180 deg:
// below sun.max_zenith_deg the night continuation takes over, see above).
// A sun range that reaches sun.max_zenith_deg goes on to 180 deg.
struct BakedRanges {
  double altitude_min_m;
  double altitude_max_m;
  double sun_zenith_min_deg;
  double sun_zenith_max_deg;
  double atmosphere_top_m;  // above the ground
  // Altitudes above the atmosphere count as its top, where a camera in space
  // is looked up (its rays enter there), and altitudes below the ground as
  // the ground, where a camera below it is looked up.
  bool containsAltitude(double altitude_m) const;
  bool containsSunZenith(double sun_zenith_deg) const;
  bool contains(double altitude_m, double sun_zenith_deg) const {
    return containsAltitude(altitude_m) && containsSunZenith(sun_zenith_deg);
  }
};

// The ranges of a bake whose tables cover `domain` (BakeContents::domain):
// what Sky::bakedRanges gives, without loading the tables.
BakedRanges bakedRangesOf(const AtmosphereDomain& domain);

template <typename Values>
struct SunAndSkyIrradianceOf {
  Values sun;  // direct sun, W m^-2 nm^-1
  Values sky;  // scattered skylight, W m^-2 nm^-1
};
using SunAndSkyIrradiance = SunAndSkyIrradianceOf<Spectrum>;
template <typename Values>
auto lookupParts(SunAndSkyIrradianceOf<Values>& v) {
  return std::tie(v.sun, v.sky);
}

// A lookup's result with every channel of a bake in place of each Spectrum
// (Sky::everyChannel): std::vector<float> for a Spectrum,
// RadianceAndTransmittanceOf<std::vector<float>> for a
// RadianceAndTransmittance, and so on for any result template of Values.
template <typename Result>
struct EveryChannelOf;
template <>
struct EveryChannelOf<Spectrum> {
  using type = std::vector<float>;
};
template <template <typename> class Result>
struct EveryChannelOf<Result<Spectrum>> {
  using type = Result<std::vector<float>>;
};

// Many view directions from one camera under one sun, as separate arrays
// (structure of arrays). Outputs: one array per channel, `count` floats each.
struct ViewRayBatch {
  const float* dir_x;
  const float* dir_y;
  const float* dir_z;
  size_t count;
};
struct SpectrumBatch {
  // One array per channel of the bake, in its channel order; null for a
  // channel not wanted. Entries past channelCount() are not written.
  float* channel[kMaxChannels];
};

// Every channel's results (Sky::everyChannel), one float per channel in the
// file's channel order.
using ChannelRadianceAndTransmittance = RadianceAndTransmittanceOf<std::vector<float>>;
using ChannelSunAndSkyIrradiance = SunAndSkyIrradianceOf<std::vector<float>>;

// What a bake's channels hold (skybake:channels in FORMAT.md).
struct BakeChannels {
  // Wavelengths (a spectral bake's too) or CieXyz.
  ChannelKind kind = ChannelKind::Wavelengths;
  // The channels' names in the file, in channel order: "440nm", ... or
  // "X", "Y", "Z".
  std::vector<std::string> names;
  // Wavelengths: each channel's wavelength. CieXyz: the wavelengths
  // integrated into X, Y, Z.
  std::vector<double> wavelengths_nm;
};

class Sky {
 public:
  // Reads a bake file. Throws Error(BadInput) for a missing, truncated,
  // corrupt or unknown-version file.
  static Sky load(const std::filesystem::path& path);
  explicit Sky(BakeFile bake);

  // What the bake's file states: the atmosphere, table sizes, domain, outputs.
  // A spectral bake's atmosphere (more than 4 wavelengths) holds its
  // wavelengths and shape; each wavelength's values are its lane group's
  // (contents().lane_groups, laneGroup(g).atmosphere()).
  const BakeContents& contents() const { return bake_.contents; }
  const AtmosphereParameters& atmosphere() const { return bake_.contents.atmosphere; }
  int channelCount() const { return atmosphere().channelCount(); }

  // ---- every channel of any bake, a spectral one of up to 64 included ----
  // A bake's channels come in lane groups of at most 4 (kMaxChannels): one
  // for an ordinary or colour bake, ceil(N / 4) for a spectral bake of N
  // wavelengths (FORMAT.md, "Spectral bakes"). Group g is an ordinary Sky of
  // its wavelengths (channels 4 g to 4 g + 3), whose every lookup works as
  // on a bake of those wavelengths alone; an ordinary bake's only group is
  // the Sky itself. The lookups below return a Spectrum, one group's lanes:
  // on a spectral Sky they throw Error(BadInput) (use everyChannel).
  int laneGroupCount() const { return lane_groups_.empty() ? 1 : static_cast<int>(lane_groups_.size()); }
  const Sky& laneGroup(int g) const;
  // The file channel of lane 0 of group g.
  int laneGroupFirstChannel(int g) const { return g * kMaxChannels; }
  // Any lookup on every channel of any bake: `lookup(group)` (or
  // `lookup(group, g)`) on each lane group in turn, each Spectrum of its
  // results joined into channelCount() values (EveryChannelOf), e.g.
  //   sky.everyChannel([&](const Sky& group) { return group.skyRadiance(camera, view_dir, sun); }).radiance
  template <typename Lookup>
  auto everyChannel(Lookup&& lookup) const;
  // The same written to the caller's arrays, one per Spectrum of the result
  // (in lookupParts order), channelCount() floats each: no allocation.
  template <typename Lookup, size_t Parts>
  void writeEveryChannel(Lookup&& lookup, const std::array<float*, Parts>& out) const;
  // Luminance (cd m^-2) of channelCount() values this bake returns
  // (illuminance in lx of an irradiance): with channelLuminanceWeights(),
  // the CIE ybar weights of all N wavelengths together, as luminance() for
  // an ordinary bake.
  double luminance(std::span<const float> channel_values) const;
  const std::vector<float>& channelLuminanceWeights() const { return channel_luminance_weights_; }

  // What the channels hold: wavelengths (spectral radiance, W m^-2 sr^-1
  // nm^-1) or CIE X, Y, Z (W m^-2 sr^-1; 683 Y is luminance).
  const BakeChannels& channels() const { return channels_; }
  // Luminance (cd m^-2) of a radiance this bake returns; illuminance (lx) of
  // an irradiance. XYZ: 683 Y; wavelengths: through the CIE 1931
  // colour-matching functions as `skybake render` converts them
  // (runtime/colour/channel_luminance.h).
  // One lane group's value: a spectral Sky refuses it (use the span form).
  double luminance(const Spectrum& value) const;
  // The weights behind luminance(): cd m^-2 per unit of each channel (0 past
  // channelCount()), for callers (and shaders) that weight lanes themselves.
  // A spectral Sky's are 0 (see channelLuminanceWeights()).
  const Spectrum& luminanceWeights() const { return luminance_weights_; }
  int orders() const { return bake_.orders_computed; }
  // The weight (0 to 1) with which a lookup whose ray starts where the sun's
  // zenith cosine is mu_s takes single scattering integrated along the ray
  // rather than from the tables (0 by day; the sun clamped to the baked
  // angles first). A GPU program all of whose rays start under a sun where
  // this is 0 can leave the integral out (runtime/glsl/README.md,
  // SKYBAKE_DAYLIGHT_LOOKUPS_ONLY).
  double integratedSingleScatteringWeightAt(double mu_s) const;
  // The bake report the file carries (JSON text, opaque to lookups).
  const std::string& bakeReportJson() const { return bake_.report_json; }

  // ---- the lookups ----
  // Each takes the sun as a Sunlight: a sun direction, or a direction and a
  // moon for a solar eclipse (docs/ECLIPSES.md; runtime/physics/
  // moon_occluder.h, eclipse_skylight.h). Under an eclipse single
  // scattering follows the moon's shadow exactly along the ray (the sun's
  // visible fraction at each point, with the moon's parallax); multiple
  // scattering and the sky's irradiance are the tables' scaled by the
  // visible fraction averaged over the neighbourhood light comes from (an
  // approximation: the light of totality comes from sunlit air outside the
  // umbra). A moon that hides no part of the sun from anywhere in the
  // atmosphere gives the uneclipsed values exactly; while it is near the
  // sun a lookup costs about 10 times a day lookup.

  // Radiance of the sky seen from `camera` looking along `view_dir`, and the
  // transmittance to where the ray leaves the atmosphere or meets the ground.
  // The ground's own reflected light is not included (see receivedRadiance).
  // shadow_length_m: the length of the ray's first part that lies in the
  // shadow of scene geometry (0 for none), for light shafts.
  RadianceAndTransmittance skyRadiance(const glm::dvec3& camera, const glm::dvec3& view_dir, const Sunlight& sun,
                                       double shadow_length_m = 0.0) const;

  // What a viewer receives along the ray, the sun disk aside: skyRadiance
  // plus, for a ray that ends on the ground, the transmitted radiance of the
  // Lambertian ground (the bake's albedo) lit by the sun and the sky.
  RadianceAndTransmittance receivedRadiance(const glm::dvec3& camera, const glm::dvec3& view_dir,
                                            const Sunlight& sun) const;

  // Radiance scattered toward `camera` between it and `point` (aerial
  // perspective), and the transmittance between them. shadow_length_m: the
  // part of the segment in the shadow of scene geometry, as for skyRadiance.
  // Under an eclipse the segment's single scattering is integrated with the
  // moon's shadow, the rest (its multiple scattering) scaled by the skylight
  // share at the segment's start, as skyRadiance scales it.
  RadianceAndTransmittance radianceToPoint(const glm::dvec3& camera, const glm::dvec3& point, const Sunlight& sun,
                                           double shadow_length_m = 0.0) const;

  // Sun and sky irradiance on a surface at `point` with unit `normal`. The sky
  // part assumes the surface sees the sky hemisphere around its normal as a
  // horizontal surface would, scaled by (1 + normal . up) / 2. Under an
  // eclipse the sun part is the disk's visible fraction of it, the sky part
  // scaled as multiple scattering is.
  SunAndSkyIrradiance irradiance(const glm::dvec3& point, const glm::dvec3& normal, const Sunlight& sun) const;

  // The direct sun's part of irradiance, W m^-2 nm^-1: the sun's irradiance
  // at the top of the atmosphere times the transmittance to it and the part
  // of its disk above the horizon (and past the moon), times the cosine of
  // incidence (0 facing away; a normal along the sun direction gives the
  // sun's irradiance at normal incidence). It needs no table a bake can
  // leave out.
  Spectrum sunIrradiance(const glm::dvec3& point, const glm::dvec3& normal, const Sunlight& sun) const;

  // The share of the uneclipsed multiple scattering and sky irradiance left
  // at `point` under sun.moon (runtime/physics/eclipse_skylight.h), per
  // channel; 1 without a moon. Sunlight::camera_skylight takes it.
  Spectrum eclipseSkylight(const glm::dvec3& point, const Sunlight& sun) const;

  // Radiance of the sun disk at the top of the atmosphere: irradiance over the
  // disk's solid angle. Multiply by the transmittance along the view ray.
  // Zero when the sun's angular radius is 0 (a point sun has no disk).
  Spectrum solarRadiance() const;

  // Transmittance along the straight segment from `a` to `b` (0 where the
  // segment passes through the ground).
  Spectrum transmittance(const glm::dvec3& a, const glm::dvec3& b) const;

  // skyRadiance for many view directions at once, uneclipsed and without
  // light shafts (vectorized across rays: a renderer's or a sweep's bulk
  // path); the same results.
  void skyRadianceBatch(const glm::dvec3& camera, const glm::dvec3& sun_dir, const ViewRayBatch& rays,
                        SpectrumBatch radiance, SpectrumBatch transmittance) const;

  const TableSampler& sampler() const { return sampler_; }
  // False for a bake without Mie scattering, which stores no single Mie table.
  bool hasSingleMie() const { return !bake_.tables.single_mie.texels.empty(); }
  // What the bake holds besides sky radiance ([scene] outputs in CONFIG.md).
  // radianceToPoint and irradiance (and receivedRadiance for a ray that ends
  // on the ground) throw Error(BadInput) for an output the bake left out.
  const SceneOutputs& outputs() const { return bake_.contents.outputs; }
  // The altitudes and sun angles the scattering tables cover (see the
  // geometry conventions above for lookups outside them).
  const BakedRanges& bakedRanges() const { return ranges_; }
  const BakeTables& tables() const { return bake_.tables; }
  // A colour bake's wavelength groups (BakeContents::wavelength_groups):
  // what each adds to X, Y, Z (ColourWavelengths) and its optical depths.
  // Empty for any other bake, and for a colour bake read from a file before
  // format version 10, whose twilight single scattering comes from its
  // X, Y, Z atmosphere.
  const std::vector<WavelengthGroupToXyz>& wavelengthGroupsToXyz() const { return wavelength_groups_to_xyz_; }
  const std::vector<Texture2D>& wavelengthOpticalDepth() const { return bake_.wavelength_optical_depth; }

 private:
  // In-scattering over [0, d - shadow] of the ray (r, mu) as the difference of
  // two lookups (see radianceToPoint).
  Spectrum differenceSegmentRadiance(double r, double mu, double mu_s, double nu, double d, double shadow, bool ground,
                                     const Spectrum& transmittance) const;

  // Single scattering (each part without its phase function) of the ray's
  // part [t_start, t_end]: from the tables (`from_tables()`, not called where
  // unused), or with the sun below the horizon integrated along the ray,
  // blended with the tables' just above it (see sky_twilight.cpp). The
  // tables are read at the ray's start and where the sun's zenith cosine is
  // `far_mu_s` (the part's end, for a segment or a light shaft): the weight
  // is the lower sun's, so that no lookup reads the single-scattering
  // tables below the horizon (a GPU upload leaves those texels out,
  // runtime/tables/gpu_tables.h).
  template <typename FromTables>
  SingleScattering singleScattering(const SunlitRay& ray, double t_start, double t_end, double far_mu_s,
                                    FromTables&& from_tables) const {
    const SunlitRay baked = withBakedSun(ray);
    SunlitRay far = ray;
    far.mu_s = far_mu_s;
    const double weight = integratedSingleScatteringWeight(std::min(baked.mu_s, withBakedSun(far).mu_s));
    SingleScattering s = weight < 1.0 ? from_tables() : SingleScattering{Spectrum(0.0f), Spectrum(0.0f)};
    if (weight > 0.0) blendInIntegratedSingleScattering(baked, t_start, t_end, weight, s);
    return s;
  }
  // The radiance scattered toward the start of a ray that ends on the ground,
  // over its part [t_start, t_end], integrated along it (for bakes whose
  // tables hold no such rays): single scattering without its phase
  // functions, and multiple scattering. `from_start` is the same ray from
  // t_start on, `to_start` the transmittance over [0, t_start].
  void groundRayRadiance(const SunlitRay& ray, double t_start, double t_end, const SunlitRay& from_start,
                         const Spectrum& to_start, SingleScattering& single, Spectrum& multiple) const;
  // skyRadiance before its parts are summed: single scattering (without
  // phase functions) and multiple scattering, for lookups that weigh them
  // apart (the eclipse lookups).
  struct SkyRadianceParts {
    bool inside = false;  // false: the ray misses the atmosphere (radiance 0, transmittance 1)
    AtmosphereRay start;  // the ray from where it is inside the atmosphere
    double mu_s = 1.0, nu = 1.0;
    double lit_from_m = 0.0;  // where scattering starts along start (past a light shaft's shadow)
    SingleScattering single{Spectrum(0.0f), Spectrum(0.0f)};
    Spectrum multiple{0.0f};
    Spectrum transmittance{1.0f};
  };
  SkyRadianceParts skyRadianceParts(const glm::dvec3& camera, const glm::dvec3& view_dir, const glm::dvec3& sun_dir,
                                    double shadow_length_m) const;
  // The lookups under an eclipse (sky_eclipse.cpp); the public lookups
  // call them when sun.moon is present.
  RadianceAndTransmittance eclipsedSkyRadiance(const glm::dvec3& camera, const glm::dvec3& view_dir,
                                               const Sunlight& sun, double shadow_length_m) const;
  RadianceAndTransmittance eclipsedRadianceToPoint(const glm::dvec3& camera, const glm::dvec3& point,
                                                   const Sunlight& sun, double shadow_length_m) const;
  SunAndSkyIrradiance eclipsedIrradiance(const glm::dvec3& point, const glm::dvec3& normal, const Sunlight& sun) const;
  // Whether the lookup is eclipsed: sun.moon checked (Error(BadInput) for a
  // centre or radius that is not finite, or a negative radius, even where
  // the radius makes it no moon) and present.
  static bool eclipsed(const Sunlight& sun);
  // Whether the moon may hide part of the sun from some point of the
  // atmosphere within reach of a ray from `point` (false: the eclipse
  // lookups are the plain ones).
  bool moonHidesSunNear(const glm::dvec3& point, const glm::dvec3& sun_dir, const Moon& moon) const;
  // The share of the plain sky irradiance at `point` left under an eclipse:
  // the eclipsed over the plain sky radiance, each summed over the same
  // cosine-weighted directions (sky_eclipse.cpp).
  Spectrum eclipsedSkyIrradianceShare(const glm::dvec3& point, const glm::dvec3& sun_dir, const Moon& moon) const;
  // `ray` with a sun outside the baked sun angles moved to the nearest one,
  // as the tables take it (see the geometry conventions above).
  SunlitRay withBakedSun(const SunlitRay& ray) const;
  // integrateSingleScattering of `ray` with this bake's tables: a colour
  // bake's per wavelength where the file has its wavelengths.
  SingleScattering integratedSingleScattering(const SunlitRay& ray, double t_start, double t_end, int segments,
                                              const MoonAlongRay* moon = nullptr) const;
  // wavelengthGroupsToXyz() of a bake with these contents.
  static std::vector<WavelengthGroupToXyz> wavelengthGroupsToXyzOf(const BakeContents& contents);
  void blendInIntegratedSingleScattering(const SunlitRay& ray, double t_start, double t_end, double weight,
                                         SingleScattering& s) const;

  // Throws Error(BadInput) naming `lookup` on a spectral Sky: its Spectrum
  // lookups would hold only one lane group's channels.
  void requireOneLaneGroup(const char* lookup) const {
    if (!lane_groups_.empty()) refuseSpectrumLookup(lookup);
  }
  [[noreturn]] void refuseSpectrumLookup(const char* lookup) const;
  // lookup(group, g) where the lookup takes the group's index, else lookup(group).
  template <typename Lookup>
  static decltype(auto) callOnGroup(Lookup& lookup, const Sky& group, int g) {
    if constexpr (std::is_invocable_v<Lookup&, const Sky&, int>) {
      return lookup(group, g);
    } else {
      return lookup(group);
    }
  }

  // A spectral bake's lane groups, each an ordinary Sky (empty otherwise).
  // Before bake_: built from the file's groups, which the constructor moves
  // out of it.
  std::vector<std::shared_ptr<const Sky>> lane_groups_;
  BakeFile bake_;
  BakeChannels channels_;
  std::vector<float> channel_luminance_weights_;
  Spectrum luminance_weights_;
  TableSampler sampler_;
  MultipleScatteringPhase multiple_shape_;  // what multiple scattering is stored divided by
  CornetteShanksPhase mie_phase_;           // the atmosphere's Mie phase function
  BakedRanges ranges_;
  double baked_mu_s_min_, baked_mu_s_max_;                      // ranges_' sun angles as zenith cosines
  std::vector<WavelengthGroupToXyz> wavelength_groups_to_xyz_;  // wavelengthGroupsToXyz
};

template <typename Lookup, size_t Parts>
void Sky::writeEveryChannel(Lookup&& lookup, const std::array<float*, Parts>& out) const {
  for (int g = 0; g < laneGroupCount(); ++g) {
    const Sky& group = laneGroup(g);
    auto result = callOnGroup(lookup, group, g);
    const auto parts = lookupParts(result);
    static_assert(std::tuple_size_v<std::decay_t<decltype(parts)>> == Parts,
                  "writeEveryChannel: one output array per Spectrum of the lookup's result");
    const int first = laneGroupFirstChannel(g), count = group.channelCount();
    [&]<size_t... K>(std::index_sequence<K...>) { (std::copy_n(&std::get<K>(parts)[0], count, out[K] + first), ...); }
    (std::make_index_sequence<Parts>{});
  }
}

template <typename Lookup>
auto Sky::everyChannel(Lookup&& lookup) const {
  using Result = std::decay_t<decltype(callOnGroup(lookup, *this, 0))>;
  typename EveryChannelOf<Result>::type out{};
  auto parts = lookupParts(out);
  constexpr size_t kParts = std::tuple_size_v<decltype(parts)>;
  std::array<float*, kParts> arrays{};
  [&]<size_t... K>(std::index_sequence<K...>) {
    ((std::get<K>(parts).resize(static_cast<size_t>(channelCount())), arrays[K] = std::get<K>(parts).data()), ...);
  }
  (std::make_index_sequence<kParts>{});
  writeEveryChannel(lookup, arrays);
  return out;
}

}  // namespace skybake
