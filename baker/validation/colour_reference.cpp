#include "baker/validation/colour_reference.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "baker/reference/path_sampler.h"
#include "data_formats/config/config.h"
#include "data_formats/config/config_at_wavelengths.h"
#include "data_formats/error.h"
#include "data_formats/queries/local_frame.h"
#include "runtime/colour/colour_bake_weights.h"
#include "runtime/colour/spectral_to_xyz.h"

namespace skybake {
namespace {

std::vector<double> colourReferenceWavelengths() {
  std::vector<double> out;
  const double step = (kColourReferenceLast_nm - kColourReferenceFirst_nm) / (kColourReferenceWavelengthCount - 1);
  for (int k = 0; k < kColourReferenceWavelengthCount; ++k) out.push_back(kColourReferenceFirst_nm + k * step);
  return out;
}

// The wavelength indices of group g (g, g + G, ... below the count).
std::vector<int> groupMembers(int group) {
  std::vector<int> out;
  for (int k = group; k < kColourReferenceWavelengthCount; k += kColourWavelengthGroups) out.push_back(k);
  return out;
}

template <typename ReadAt>
ColourReferenceAtmospheres atmospheresFrom(ReadAt&& read_at) {
  ColourReferenceAtmospheres out;
  out.wavelengths_nm = colourReferenceWavelengths();
  // The 41 wavelengths' colour-matching weights, by the rule a bake's
  // channels go through (SpectralToXyz): one formula for both.
  const colour::SpectralToXyz to_xyz(out.wavelengths_nm);
  for (int g = 0; g < kColourWavelengthGroups; ++g) {
    std::vector<double> wavelengths;
    glm::dmat4 lanes_to_xyz(0.0);
    const std::vector<int> members = groupMembers(g);
    for (size_t lane = 0; lane < members.size(); ++lane) {
      wavelengths.push_back(out.wavelengths_nm[members[lane]]);
      const colour::Xyz& w = to_xyz.weight(members[lane]);
      lanes_to_xyz[static_cast<int>(lane)] = glm::dvec4(w.x, w.y, w.z, 0.0);
    }
    out.groups.push_back(read_at(wavelengths).atmosphere);
    out.group_lanes_to_xyz.push_back(lanes_to_xyz);
  }
  out.guide = std::make_shared<LitAirGuide>(out.groups.front());
  return out;
}

// Independent seeds per group and half, from the query's own.
uint64_t groupSeed(uint64_t seed, int group, int half) {
  return stableHash(fmt::format("{:016x} colour group {} half {}", seed, group, half));
}

// The two halves, each summed over the groups, and their mean.
template <typename EstimateFn>
ColourEstimate sumOverGroups(const ColourReferenceAtmospheres& colour, EstimateFn&& estimate) {
  std::array<SpectrumD, 2> half{SpectrumD(0.0), SpectrumD(0.0)};
  SpectrumD variance(0.0);
  for (int h = 0; h < 2; ++h) {
    for (size_t g = 0; g < colour.groups.size(); ++g) {
      const ReferenceEstimate e = estimate(
          ReferenceSolver(colour.groups[g], ReferenceSolver::VertexSampling::TowardLitAirBelowHorizon, colour.guide),
          colour.group_lanes_to_xyz[g], static_cast<int>(g), h);
      half[h] += e.value;
      variance += e.standard_error * e.standard_error;  // groups and halves trace independent paths
    }
  }
  // The mean of the halves has a quarter of the summed variance.
  return {0.5 * (half[0] + half[1]), 0.5 * glm::sqrt(variance), 0.5 * (half[0] - half[1])};
}

}  // namespace

ColourReferenceAtmospheres colourReferenceAtmospheres(std::string_view toml_text, const std::string& source,
                                                      const std::filesystem::path& spectrum_directory) {
  return atmospheresFrom([&](const std::vector<double>& wavelengths) {
    return configAtWavelengths(toml_text, source, spectrum_directory, wavelengths);
  });
}

ColourReferenceAtmospheres colourReferenceAtmospheresFromFile(const std::filesystem::path& config_path) {
  return atmospheresFrom(
      [&](const std::vector<double>& wavelengths) { return configFileAtWavelengths(config_path, wavelengths); });
}

void requireConfigOfBake(const std::filesystem::path& config_path, const AtmosphereParameters& bake,
                         const std::vector<AtmosphereParameters>& lane_groups) {
  if (bake.storesLaneGroups()) {
    // Read at more than 4 wavelengths a config gives no one atmosphere: each
    // group's wavelengths give that group's.
    if (lane_groups.empty())
      throw Error(ErrorKind::Internal, "requireConfigOfBake: a spectral bake without its groups");
    for (const AtmosphereParameters& group : lane_groups) requireConfigOfBake(config_path, group);
    return;
  }
  if (bake.storesCieXyz()) {
    // A colour bake states its X, Y, Z atmosphere, made from its passes'
    // atmospheres by the weights the bake used (colour_bake_weights.h).
    const BakeConfig config = loadConfigFile(config_path);
    if (!config.atmosphere.storesCieXyz() || config.colour_groups.empty()) {
      throwBadInput(fmt::format("{}: not a colour bake's config (channels.store = \"cie_xyz\"), but the bake is one",
                                config_path.string()));
    }
    AtmosphereParameters own =
        colour::ColourBakeWeights(config.colour_groups).cieXyzAtmosphere(config.atmosphere, config.colour_groups);
    own.sun_max_zenith_deg = bake.sun_max_zenith_deg;
    if (own == bake) return;
    throwBadInput(fmt::format(
        "{}: its X, Y, Z atmosphere (from {} wavelengths) is not the colour bake's: give the config the bake was "
        "made from",
        config_path.string(), config.atmosphere.wavelengths_nm.size()));
  }
  AtmosphereParameters own = configFileAtWavelengths(config_path, bake.wavelengths_nm).atmosphere;
  own.sun_max_zenith_deg = bake.sun_max_zenith_deg;
  if (own == bake) return;
  throwBadInput(fmt::format(
      "{}: its atmosphere at the bake's wavelengths ({} nm) is not the bake's: give the config the bake was made "
      "from",
      config_path.string(), fmt::join(bake.wavelengths_nm, ", ")));
}

int colourGroupHalfPaths(int paths) {
  if (paths <= 0) return 0;
  constexpr int kShares = 2 * kColourWavelengthGroups;
  return std::max(kReplicates, (paths + kShares - 1) / kShares);
}

ColourEstimate colourRadianceReference(const ColourReferenceAtmospheres& colour, const ReferenceRay& ray, int paths,
                                       uint64_t seed, const Moon& moon) {
  const int half_paths = colourGroupHalfPaths(paths);
  return sumOverGroups(colour, [&](const ReferenceSolver& solver, const glm::dmat4& to_xyz, int g, int h) {
    return solver.mappedRadiance(ray, half_paths, groupSeed(seed, g, h), to_xyz, moon);
  });
}

ColourEstimate colourSkyIrradianceReference(const ColourReferenceAtmospheres& colour, const glm::dvec3& point,
                                            const glm::dvec3& sun, int paths, uint64_t seed, const Moon& moon) {
  const int half_paths = colourGroupHalfPaths(paths);
  return sumOverGroups(colour, [&](const ReferenceSolver& solver, const glm::dmat4& to_xyz, int g, int h) {
    return solver.mappedSkyIrradiance(point, sun, half_paths, groupSeed(seed, g, h), to_xyz, moon);
  });
}

ColourReferenceValues computeColourReference(const ColourReferenceAtmospheres& colour, const QuerySet& queries,
                                             const ReferenceSettings& settings, ProgressSink& progress) {
  const AtmosphereParameters& a = colour.groups.front();  // the geometry every group shares
  ReferenceCache cache(settings.cache_directory, colour.groups, settings.paths);
  auto radianceCacheKey = [&](size_t i) { return "xyz " + radianceKey(queries.radiance[i]); };
  auto irradianceCacheKey = [&](size_t i) { return "xyz " + irradianceKey(queries.irradiance[i]); };
  ColourReferenceValues out;
  out.radiance.resize(queries.radiance.size());
  out.irradiance.resize(queries.irradiance.size());
  std::vector<size_t> missing;
  for (size_t i = 0; i < queries.radiance.size(); ++i) {
    if (auto hit = cache.find(radianceCacheKey(i))) {
      out.radiance[i] = *hit;
    } else {
      missing.push_back(i);
    }
  }
  for (size_t i = 0; i < queries.irradiance.size(); ++i) {
    if (auto hit = cache.find(irradianceCacheKey(i))) {
      out.irradiance[i] = *hit;
    } else {
      missing.push_back(queries.radiance.size() + i);
    }
  }
  out.cached = static_cast<int>(queries.radiance.size() + queries.irradiance.size() - missing.size());
  auto compute = [&](size_t item) {
    if (item < queries.radiance.size()) {
      const RadianceQuery& q = queries.radiance[item];
      const QueryGeometry g = geometryOf(a, q);
      const ColourEstimate e =
          colourRadianceReference(colour, {g.camera, g.view, g.sun, q.distance_m}, referencePathsFor(q, settings.paths),
                                  stableHash(radianceKey(q)), g.moon);
      out.radiance[item] = {e.value, e.standard_error, SpectrumD(0.0), e.half_difference};
    } else {
      const IrradianceQuery& q = queries.irradiance[item - queries.radiance.size()];
      const QueryGeometry g = geometryOf(a, q);
      const ColourEstimate e =
          colourSkyIrradianceReference(colour, g.camera, g.sun, settings.paths, stableHash(irradianceKey(q)), g.moon);
      out.irradiance[item - queries.radiance.size()] = {e.value, e.standard_error, SpectrumD(0.0), e.half_difference};
    }
  };
  auto store = [&](size_t item) {
    if (item < queries.radiance.size()) {
      cache.store(radianceCacheKey(item), out.radiance[item]);
    } else {
      const size_t i = item - queries.radiance.size();
      cache.store(irradianceCacheKey(i), out.irradiance[i]);
    }
  };
  out.seconds = computeInCheckpointedBatches(missing, "colour reference", progress, cache, compute, store);
  out.computed = static_cast<int>(missing.size());
  return out;
}

}  // namespace skybake
