#include "baker/bake/colour_bake.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "baker/bake/bake_passes.h"
#include "baker/bake/bake_policy.h"
#include "baker/bake/process_usage.h"
#include "baker/stages/order_shapes.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"
#include "runtime/colour/colour_bake_weights.h"
#include "runtime/physics/multiple_scattering_phase.h"
#include "runtime/tables/table_sampler.h"

namespace skybake {
namespace {

using colour::ColourBakeWeights;

// The colour-matching weights of a pass's lanes: mix[c][l] is what one unit
// of lane l adds to channel c.
std::array<Spectrum, kMaxChannels> passMix(const ColourBakeWeights& w, int first_wavelength, int lanes) {
  std::array<Spectrum, kMaxChannels> mix{};
  mix.fill(Spectrum(0.0f));
  for (int c = 0; c < kCieXyzChannels; ++c) {
    for (int l = 0; l < lanes; ++l) mix[c][l] = static_cast<float>(w.colourMatching(c, first_wavelength + l));
  }
  return mix;
}

Spectrum mixed(const std::array<Spectrum, kMaxChannels>& mix, const Spectrum& lanes) {
  Spectrum out(0.0f);
  for (int c = 0; c < kCieXyzChannels; ++c) {
    for (int l = 0; l < kMaxChannels; ++l) out[c] += mix[c][l] * lanes[l];
  }
  return out;
}

// sum += the pass's linear table in X, Y, Z; a table the pass left out (no
// texels) adds nothing.
void addLinear(const std::array<Spectrum, kMaxChannels>& mix, const std::vector<Spectrum>& pass,
               std::vector<Spectrum>& sum) {
  if (pass.empty()) return;
  if (sum.empty()) sum.assign(pass.size(), Spectrum(0.0f));
  if (sum.size() != pass.size()) throw Error(ErrorKind::Internal, "colour bake: passes of different table sizes");
  for (size_t i = 0; i < sum.size(); ++i) sum[i] += mixed(mix, pass[i]);
}

template <typename Texture>
Texture zeroedLike(const Texture& t) {
  Texture z = t;
  std::fill(z.texels.begin(), z.texels.end(), Spectrum(0.0f));
  return z;
}

// What the passes' orders added, in X, Y, Z.
void addPassOrders(const BakeReport& pass, const std::array<Spectrum, kMaxChannels>& mix, BakeReport& report) {
  for (size_t k = 0; k < pass.orders.size(); ++k) {
    if (k == report.orders.size()) report.orders.push_back({pass.orders[k].order, Spectrum(0.0f), Spectrum(0.0f)});
    report.orders[k].mean_radiance += mixed(mix, pass.orders[k].mean_radiance);
    report.orders[k].mean_irradiance += mixed(mix, pass.orders[k].mean_irradiance);
  }
}

}  // namespace

BakeOutput bakeCieXyz(const BakeConfig& settled, int threads, ProgressSink& progress) {
  if (!settled.atmosphere.storesCieXyz() || settled.colour_groups.empty()) {
    throw Error(ErrorKind::Internal, "bakeCieXyz: not a settled colour config");
  }
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = processCpuSeconds();
  const ColourBakeWeights weights(settled.colour_groups);
  BakeOutput out;
  out.file.contents = bakeContents(settled);
  const BakeContents& contents = out.file.contents;
  // The stored tables' texels: every pass stores on the same ones.
  const TableSampler stored(contents.domain, contents.sizes);
  const TableSampler stored_density(contents.domain, contents.densityTableSizes());
  const MultipleScatteringPhase xyz_shape(settled.atmosphere);
  BakeTables& xyz = out.file.tables;
  // Every wavelength's optical depth, for the effective depth of sunlight
  // (ColourBakeWeights::effectiveOpticalDepth): texel-major, small (2D).
  std::vector<double> optical_depths;
  const int wavelengths = weights.wavelengthCount();
  int first_wavelength = 0;
  int orders_computed = 0;
  for (size_t g = 0; g < settled.colour_groups.size(); ++g) {
    BakeConfig pass_config = passConfig(settled, g);
    // Each pass keeps every bit: X, Y, Z are rounded once, as stored.
    pass_config.bake.stored_fraction_bits = kFloatFractionBits;
    const int lanes = pass_config.atmosphere.channelCount();
    PassProgress pass_progress(progress, g, settled.colour_groups.size());
    BakeOutput pass = bakeWavelengthPass(pass_config, threads, pass_progress);
    BakeTables& t = pass.file.tables;
    const std::array<Spectrum, kMaxChannels> mix = passMix(weights, first_wavelength, lanes);
    const auto conversion_start = std::chrono::steady_clock::now();
    if (g == 0) {
      xyz.optical_depth = zeroedLike(t.optical_depth);
      xyz.single_rayleigh = zeroedLike(t.single_rayleigh);
      xyz.single_mie = zeroedLike(t.single_mie);
      xyz.multiple_scattering = zeroedLike(t.multiple_scattering);
      xyz.irradiance = zeroedLike(t.irradiance);
      xyz.multiple_density = zeroedLike(t.multiple_density);
      optical_depths.assign(t.optical_depth.texels.size() * static_cast<size_t>(wavelengths), 0.0);
    }
    // Kept as the pass stored it: twilight lookups integrate single
    // scattering per wavelength from it (FORMAT.md "Colour bakes").
    out.file.wavelength_optical_depth.push_back(t.optical_depth);
    for (size_t i = 0; i < t.optical_depth.texels.size(); ++i) {
      for (int l = 0; l < lanes; ++l) {
        optical_depths[i * static_cast<size_t>(wavelengths) + first_wavelength + l] = t.optical_depth.texels[i][l];
      }
    }
    addLinear(mix, t.single_rayleigh.texels, xyz.single_rayleigh.texels);
    addLinear(mix, t.single_mie.texels, xyz.single_mie.texels);
    addLinear(mix, t.irradiance.texels, xyz.irradiance.texels);
    const MultipleScatteringPhase pass_shape(pass_config.atmosphere);
    if (!t.multiple_scattering.texels.empty()) {
      addMixedReshaped(stored, TexelLayout::Scattering, t.multiple_scattering, pass_shape, xyz_shape, mix,
                       xyz.multiple_scattering);
    }
    if (!t.multiple_density.texels.empty()) {
      addMixedReshaped(stored_density, TexelLayout::Density, t.multiple_density, pass_shape, xyz_shape, mix,
                       xyz.multiple_density);
    }
    pass.report.stages.push_back(
        {"colour_sum", 0, std::chrono::duration<double>(std::chrono::steady_clock::now() - conversion_start).count()});
    addPassRun(pass.report, g, pass_config.atmosphere.wavelengths_nm, out.report);
    addPassOrders(pass.report, mix, out.report);
    orders_computed = std::max(orders_computed, pass.file.orders_computed);
    first_wavelength += lanes;
  }
  for (size_t i = 0; i < xyz.optical_depth.texels.size(); ++i) {
    const std::span<const double> tau(optical_depths.data() + i * static_cast<size_t>(wavelengths),
                                      static_cast<size_t>(wavelengths));
    for (int c = 0; c < kCieXyzChannels; ++c) {
      xyz.optical_depth.texels[i][c] = static_cast<float>(weights.effectiveOpticalDepth(c, tau));
    }
  }
  settleStoredTables(contents, xyz);

  BakeReport& report = out.report;
  finishPassesReport(start, cpu_start, report);
  out.file.config_toml = configToToml(settled);
  out.file.orders_computed = orders_computed;
  out.file.report_json = report.toJson();
  return out;
}

}  // namespace skybake
