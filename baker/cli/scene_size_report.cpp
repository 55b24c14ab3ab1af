#include "baker/cli/scene_size_report.h"

#include <array>
#include <cmath>

#include <fmt/format.h>

#include "baker/bake/bake_policy.h"
#include "data_formats/angles.h"
#include "data_formats/parameterization/texture_mapping.h"

namespace skybake {
namespace {

std::array<int, 4> scatteringSizes(const TextureSizes& s) {
  return {s.scattering_r, s.scattering_mu, s.scattering_mu_s, s.scattering_nu};
}

// The 4D texels a bake of these sizes stores: single Rayleigh, single Mie and
// multiple scattering, and the density on its own view axis (densitySizes).
double storedTexels(const TextureSizes& s) { return 3.0 * s.scatteringTexels() + densitySizes(s).scatteringTexels(); }

std::string sizesText(const std::array<int, 4>& s) { return fmt::format("{} x {} x {} x {}", s[0], s[1], s[2], s[3]); }

// "chosen" or "given" per axis of a resolution table that may leave axes to the bake.
std::string origin(const std::optional<std::array<int, 4>>& given) {
  int count = 0;
  if (given) {
    for (int n : *given) count += n != TextureSizes::kChosenByTheBake;
  }
  return count == 0 ? "chosen" : count == 4 ? "as the config gives them" : "partly as the config gives them";
}

}  // namespace

std::optional<SceneSizeChoice> sceneSizeChoice(const BakeConfig& requested, const BakeConfig& settled) {
  if (!sceneDomain(settled).narrowed() || !settled.sizes.iteration) return std::nullopt;
  const std::array<int, 4> whole = scatteringSizes(requested.sizes);
  const std::array<int, 4> stored = scatteringSizes(settled.sizes);
  const std::array<int, 4> iteration = *settled.sizes.iteration;
  const double share = storedTexels(settled.sizes) / storedTexels(requested.sizes);
  const std::string stored_origin = origin(requested.sizes.scene);
  const std::string iteration_origin = origin(requested.sizes.iteration);
  SceneSizeChoice choice;
  std::string ranges;
  if (const auto& a = settled.scene_ranges.altitude_m)
    ranges += fmt::format(", altitudes {:.0f} to {:.0f} m", (*a)[0], (*a)[1]);
  const AtmosphereDomain domain = sceneDomain(settled);
  const ScatteringSizes sizes = ScatteringSizes::fromTextureSizes(settled.sizes);
  if (settled.scene_ranges.sun_zenith_deg) {
    ranges += fmt::format(", sun zenith {:.1f} to {:.1f} deg",
                          degreesFromRadians(std::acos(muSFromScatteringTexel(domain, sizes, sizes.mu_s - 1))),
                          degreesFromRadians(std::acos(muSFromScatteringTexel(domain, sizes, 0))));
  }
  choice.description = fmt::format(
      "scene sizes: stored tables {} ({}{}), iteration over the whole atmosphere {} ({}), from the whole domain's "
      "{} (resolution.scattering): {:.1f} % of the whole bake's 4D texels. The bake keeps the whole axes' own "
      "altitude and sun texels over the scene's ranges (widened to the next texel), 11/16 of the view and 10/16 "
      "of the view-sun texels (docs/LEAVE_OUT.md); resolution.scene and resolution.iteration set them",
      sizesText(stored), stored_origin, ranges, sizesText(iteration), iteration_origin, sizesText(whole),
      100.0 * share);
  return choice;
}

}  // namespace skybake
