#include "baker/bake/bake.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <optional>

#include "baker/stages/direct_irradiance_table.h"
#include "baker/stages/indirect_irradiance_table.h"
#include "baker/stages/multiple_scattering_table.h"
#include "baker/stages/openmp_threads.h"
#include "baker/stages/optical_depth_table.h"
#include "baker/stages/order_shapes.h"
#include "baker/stages/row_sun_texels.h"
#include "baker/stages/scattering_density_kernel.h"
#include "baker/stages/scattering_density_table.h"
#include "baker/stages/scene_tables.h"
#include "baker/stages/single_scattering_tables.h"

#include <fmt/format.h>

#include "baker/bake/altitude_prefilter.h"
#include "baker/bake/bake_policy.h"
#include "baker/bake/colour_bake.h"
#include "baker/bake/order_convergence.h"
#include "baker/bake/process_usage.h"
#include "baker/bake/slice_tail.h"
#include "baker/bake/spectral_bake.h"
#include "baker/bake/sun_prefilter.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"
#include "data_formats/parameterization/texture_mapping.h"

namespace skybake {
namespace {

Spectrum meanOf(const std::vector<Spectrum>& texels) {
  SpectrumD sum(0.0);  // long sum: double
  for (const Spectrum& s : texels) sum += SpectrumD(s);
  return Spectrum(sum / static_cast<double>(std::max<size_t>(texels.size(), 1)));
}

// The mean over all texels from the slices' means (every slice has as many texels).
Spectrum meanOfSlices(const std::vector<SpectrumD>& slice_means) {
  SpectrumD sum(0.0);
  for (const SpectrumD& m : slice_means) sum += m;
  return Spectrum(sum / static_cast<double>(std::max<size_t>(slice_means.size(), 1)));
}

void addScaled(std::vector<Spectrum>& sum, const std::vector<Spectrum>& delta, const Spectrum& scale) {
  for (size_t i = 0; i < sum.size(); ++i) sum[i] += delta[i] * scale;
}

// The last order's mean radiance over the sum of all orders so far, worst
// channel: how much the last order still changed the sky on average (the
// decision takes the worst slice instead, OrderConvergence). A channel whose
// total is zero (nothing scatters) has converged trivially; a non-finite one
// never has (infinity: automatic orders then run to the cap and say so).
float lastOrderShare(const std::vector<OrderContribution>& orders, int channels) {
  float worst = 0.0f;
  for (int c = 0; c < channels; ++c) {
    float total = 0.0f;
    for (const OrderContribution& o : orders) total += o.mean_radiance[c];
    const float last = orders.back().mean_radiance[c];
    if (!std::isfinite(total) || !std::isfinite(last)) return std::numeric_limits<float>::infinity();
    if (total > 0.0f) worst = std::max(worst, last / total);
  }
  return worst;
}

// Above this ratio between successive orders a geometric tail is too uncertain
// (and too large) to add: such atmospheres need more computed orders.
constexpr float kMaxTailRatio = 0.8f;

// The table's ratio between the last two orders' mean radiance, per
// channel, if a tail can be estimated from it; otherwise why not.
TailEstimate tableTailRatio(const std::vector<OrderContribution>& orders, int channels) {
  TailEstimate tail;
  const size_t n = orders.size();
  if (n < 3) {
    tail.reason = "not applied: needs at least 3 orders to estimate the ratio";
    return tail;
  }
  for (int c = 0; c < channels; ++c) {
    const float previous = orders[n - 2].mean_radiance[c];
    const float last = orders[n - 1].mean_radiance[c];
    // A channel in which neither order added light has no tail: its ratio
    // stays 0 and the other channels' tails still apply.
    if (previous == 0.0f && last == 0.0f) continue;
    if (!(previous > 0.0f)) {
      tail.ratio = Spectrum(0.0f);
      tail.reason = fmt::format("not applied: order {} added light in channel {} where order {} added none",
                                orders[n - 1].order, c, orders[n - 2].order);
      return tail;
    }
    tail.ratio[c] = last / previous;
    if (!(tail.ratio[c] > 0.0f && tail.ratio[c] < kMaxTailRatio)) {
      tail.reason = fmt::format("not applied: order ratio {} outside (0, {})", tail.ratio[c], kMaxTailRatio);
      tail.ratio = Spectrum(0.0f);
      return tail;
    }
  }
  tail.applied = true;
  return tail;
}

// Adds the orders after the last computed one to the stored density, each
// slice's as its own multiple of the last order (SliceTail); the stored
// multiple scattering and sky irradiance, integrated from that density
// afterwards, then hold them too. The SliceTail, or none where the table's
// ratio allows no tail (tail.reason says why).
std::optional<SliceTail> addTailEstimate(const TableSampler& sampler, const std::vector<OrderContribution>& orders,
                                         const OrderConvergence& convergence, int channels,
                                         const Texture4D& last_density, const MultipleScatteringPhase& last_shape,
                                         const MultipleScatteringPhase& stored_shape, Texture4D& density_sum,
                                         TailEstimate& tail) {
  tail = tableTailRatio(orders, channels);
  if (!tail.applied) return std::nullopt;
  std::optional<SliceTail> slices(std::in_place, sampler, convergence.sliceMeans(2), convergence.sliceMeans(1),
                                  convergence.sliceMeans(0), tail.ratio, kMaxTailRatio);
  addReshaped(sampler, TexelLayout::Density, last_density, last_shape, stored_shape, slices->scales(), density_sum);
  tail.reason = fmt::format(
      "applied after order {}: the remaining orders as a series whose ratio relaxes from each slice's last toward "
      "the table's (at most {:.3g} times the last order)",
      orders.back().order, slices->largestScale());
  return slices;
}

// A narrowed scene's stored tables: its scattering density, computed on the
// scene's own texels (on densitySizes' view axis, as the whole domain's) order
// by order from the whole domain's previous order. Interpolated from the
// whole domain's summed density instead, it was interpolated twice (there,
// then again at each lookup), which smoothed the twilight sky's fall with the
// sun angle and altitude: rays toward the ground integrate it in a bake
// without views below the horizon, and radiance to a point does in twilight.
struct SceneDensity {
  TableSampler sampler;          // the stored radiance tables' texels
  TableSampler density_sampler;  // the stored density's
  StageContext ctx;
  StageContext density_ctx;
  ScatteringDensityKernel kernel;  // on density_sampler's texels
  Texture4D sum;                   // orders 2 .. N, each divided by the stored shape (as in the file)
  Texture4D last;                  // order N's, divided by its own shape

  SceneDensity(const AtmosphereParameters& a, const AtmosphereDomain& domain, const TextureSizes& sizes,
               ProgressSink& progress)
      : sampler(domain, sizes),
        density_sampler(domain, densitySizes(sizes)),
        ctx{a, sampler, progress},
        density_ctx{a, density_sampler, progress},
        sum(density_sampler.scatteringSizes().r, density_sampler.scatteringSizes().mu,
            density_sampler.scatteringSizes().mu_s, density_sampler.scatteringSizes().nu) {}
  SceneDensity(const SceneDensity&) = delete;  // the contexts refer to the samplers
  SceneDensity& operator=(const SceneDensity&) = delete;
};

class StageRunner {
 public:
  StageRunner(ProgressSink& progress, BakeReport& report) : progress_(progress), report_(report) {}

  template <typename Fn>
  auto run(const std::string& stage, int order, size_t work_units, Fn&& fn) {
    progress_.beginStage(order > 1 ? stage + " (order " + std::to_string(order) + ")" : stage, work_units);
    const auto start = std::chrono::steady_clock::now();
    auto finish = [&] {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      report_.stages.push_back({stage, order, seconds});
      progress_.endStage(seconds);
    };
    if constexpr (std::is_void_v<decltype(fn())>) {
      fn();
      finish();
    } else {
      auto result = fn();
      finish();
      return result;
    }
  }

 private:
  ProgressSink& progress_;
  BakeReport& report_;
};

}  // namespace

BakeOutput bakeAtmosphere(const BakeConfig& requested, int threads, ProgressSink& progress) {
  const BakeConfig config = settledBakeConfig(requested);
  if (config.atmosphere.storesCieXyz()) return bakeCieXyz(config, threads, progress);
  if (config.atmosphere.storesLaneGroups()) return bakeSpectral(config, threads, progress);
  return bakeWavelengthPass(config, threads, progress);
}

BakeOutput bakeWavelengthPass(const BakeConfig& config, int threads, ProgressSink& progress) {
  if (config.atmosphere.storesCieXyz() || config.atmosphere.storesLaneGroups()) {
    throw Error(ErrorKind::Internal,
                "bakeWavelengthPass: a colour or spectral bake's config (bake each wavelength group)");
  }
  const ScopedOpenMpThreads thread_count(threads);
  BakeOutput out;
  BakeReport& report = out.report;
  report.threads = thread_count.threads();
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = processCpuSeconds();

  const AtmosphereParameters& a = config.atmosphere;
  // The orders iterate over the whole domain; a scene that narrows it gets
  // its stored tables afterwards (narrowTablesToScene).
  const TableSampler sampler(AtmosphereDomain::fromParameters(a), iterationTextureSizes(config));
  const StageContext ctx{a, sampler, progress};
  const ScatteringSizes& s = sampler.scatteringSizes();
  const size_t rows_4d = static_cast<size_t>(s.r) * s.mu;
  const size_t slices_4d = static_cast<size_t>(s.r) * s.mu_s;
  StageRunner stage(progress, report);

  BakeTables& tables = out.file.tables;
  tables.optical_depth =
      stage.run("transmittance", 0, config.sizes.transmittance_r, [&] { return computeOpticalDepthTable(ctx); });
  const Texture2D& optical_depth = tables.optical_depth;
  Texture2D delta_irradiance = stage.run("direct_irradiance", 1, config.sizes.irradiance_r,
                                         [&] { return computeDirectIrradianceTable(ctx, optical_depth); });
  stage.run("single_scattering", 1, rows_4d,
            [&] { computeSingleScatteringTables(ctx, optical_depth, tables.single_rayleigh, tables.single_mie); });
  OrderConvergence convergence(sampler, a.channelCount());
  {
    const std::vector<SpectrumD> single =
        sliceMeanSingleScatteringRadiance(sampler, tables.single_rayleigh, tables.single_mie, a.mie_phase_g);
    convergence.add(single);
    report.orders.push_back({1, meanOfSlices(single), Spectrum(0.0f)});
  }

  // Orders 2..N. Each order's scattering density is computed on half the
  // view axis (densitySizes) and summed there, as the file stores it. Each order's radiance, which only feeds
  // the next order's density (an integral over every direction, which smooths it), is
  // on coarser view and view-sun axes (orderRadianceSizes). The stored
  // multiple scattering is then the summed density, tail included,
  // integrated along each ray once, rather than every order's integrated
  // and summed: the integral is linear in the density. Texels are divided by
  // the multiple-scattering shape at their r and nu
  // (runtime/physics/multiple_scattering_phase.h): while iterating, each order's by
  // its own; summed into the file, by the stored one, which a lookup
  // multiplies back.
  const TableSampler order_sampler(sampler.domain(), orderRadianceSizes(sampler.sizes()));
  const StageContext order_ctx{a, order_sampler, progress};
  const TableSampler density_sampler(sampler.domain(), densitySizes(sampler.sizes()));
  const StageContext density_ctx{a, density_sampler, progress};
  const ScatteringSizes& ds = density_sampler.scatteringSizes();
  Texture4D density_sum(ds.r, ds.mu, ds.mu_s, ds.nu);  // orders 2..N, on density_sampler's texels
  const ScatteringSizes& os = order_sampler.scatteringSizes();
  const MultipleScatteringPhase stored_shape(a);
  std::optional<MultipleScatteringPhase> previous_shape;  // the last computed order's
  tables.irradiance = Texture2D(config.sizes.irradiance_mu_s, config.sizes.irradiance_r);
  Texture4D delta_multiple;  // the last order's radiance, on order_sampler's texels
  Texture4D last_density;    // the last order's density, on density_sampler's texels
  const BakeSettings& settings = config.bake;
  const int last_order = settings.auto_orders ? settings.max_orders : settings.orders;
  report.orders_decision.automatic = settings.auto_orders;
  report.orders_decision.tolerance = settings.auto_orders ? settings.order_tolerance : 0.0;
  report.orders_decision.cap = settings.auto_orders ? settings.max_orders : 0;
  std::optional<ScatteringDensityKernel> density_kernel;  // on density_sampler's texels
  if (last_order >= 2) {
    density_kernel =
        stage.run("density_kernel", 0, s.r, [&] { return makeScatteringDensityKernel(density_ctx, optical_depth); });
  }
  // A scene that narrows the domain stores its 4D tables on its own texels.
  const AtmosphereDomain scene_domain = sceneDomain(config);
  std::optional<SceneDensity> scene;
  if (scene_domain.narrowed()) {
    scene.emplace(a, scene_domain, config.sizes, progress);
    if (last_order >= 2) {
      scene->kernel = stage.run("scene_density_kernel", 0, scene->density_sampler.scatteringSizes().r,
                                [&] { return makeScatteringDensityKernel(scene->density_ctx, optical_depth); });
    }
  }
  bool single_prefiltered = false;  // the single-scattering tables (altitude_prefilter.h)
  for (int order = 2; order <= last_order; ++order) {
    const MultipleScatteringPhase order_shape(a, order);
    const OrderRadiance previous{order - 1, tables.single_rayleigh, tables.single_mie, delta_multiple,
                                 previous_shape ? *previous_shape : stored_shape};
    // Order 1 is read from the single-scattering tables, later orders from order_sampler's.
    const StageContext& previous_ctx = order == 2 ? ctx : order_ctx;
    // Every order's density on density_sampler's texels (densitySizes).
    Texture4D density = stage.run("scattering_density", order, slices_4d, [&] {
      return computeScatteringDensityTable(density_ctx, *density_kernel, previous, previous_ctx.sampler, order_shape,
                                           delta_irradiance);
    });
    addReshaped(density_sampler, TexelLayout::Density, density, order_shape, stored_shape, Spectrum(1.0f), density_sum);
    if (scene) {
      const ScatteringSizes& ss = scene->density_sampler.scatteringSizes();
      scene->last = stage.run("scene_density", order, static_cast<size_t>(ss.r) * ss.mu_s, [&] {
        return computeScatteringDensityTable(scene->density_ctx, scene->kernel, previous, previous_ctx.sampler,
                                             order_shape, delta_irradiance);
      });
      addReshaped(scene->density_sampler, TexelLayout::Density, scene->last, order_shape, stored_shape, Spectrum(1.0f),
                  scene->sum);
    }
    if (order == 2) {
      // Order 2's densities were the last to read the single-scattering
      // tables at their own r texels. Order 1's sky irradiance, stored, is
      // summed at rows between them, from the tables as the lookups blend
      // them (altitude_prefilter.h); later orders' irradiance feeds only
      // the next order's light reflected by the ground, on the r texel of
      // the ground, which prefiltering leaves as it is.
      prefilterAcrossAltitude(tables.single_rayleigh);
      prefilterAcrossAltitude(tables.single_mie);
      single_prefiltered = true;
    }
    delta_irradiance = stage.run("indirect_irradiance", order - 1, config.sizes.irradiance_r,
                                 [&] { return computeIndirectIrradianceTable(previous_ctx, optical_depth, previous); });
    // Order 1's sky irradiance is stored; the later orders' come from the stored multiple scattering below.
    if (order == 2) tables.irradiance = delta_irradiance;
    report.orders.back().mean_irradiance = meanOf(delta_irradiance.texels);

    last_density = std::move(density);  // the previous order's is needed no longer
    delta_multiple = stage.run("order_radiance", order, static_cast<size_t>(os.r) * os.mu, [&] {
      return computeMultipleScatteringTable(order_ctx, optical_depth, density_sampler, last_density, order_shape,
                                            kOrderRadianceRaySegments);
    });
    const std::vector<SpectrumD> order_slices = sliceMeanShapedRadiance(order_sampler, delta_multiple, order_shape);
    convergence.add(order_slices);
    report.orders.push_back({order, meanOfSlices(order_slices), Spectrum(0.0f)});
    previous_shape = order_shape;
    OrdersDecision& decision = report.orders_decision;
    decision.mean_last_order_share = lastOrderShare(report.orders, a.channelCount());
    const SliceShare worst = convergence.worstLastShare();
    decision.last_order_share = static_cast<float>(worst.share);
    decision.worst_altitude_m = worst.altitude_m;
    decision.worst_sun_zenith_deg = worst.sun_zenith_deg;
    if (settings.auto_orders && decision.last_order_share < settings.order_tolerance) {
      report.orders_decision.converged = true;
      break;
    }
  }

  // Orders 3 and up (and a tail that follows one) were summed on density_sampler's texels.
  if (config.bake.tail_estimate) {
    const MultipleScatteringPhase& last_shape = previous_shape ? *previous_shape : stored_shape;
    const std::optional<SliceTail> slice_tail =
        addTailEstimate(density_sampler, report.orders, convergence, a.channelCount(), last_density, last_shape,
                        stored_shape, density_sum, report.tail);
    if (scene && slice_tail) {
      // The scene's texels take the whole domain's tail at their altitude and sun.
      addReshaped(scene->density_sampler, TexelLayout::Density, scene->last, last_shape, stored_shape,
                  slice_tail->scalesAtSlicesOf(scene->density_sampler), scene->sum);
    }
  } else {
    report.tail.reason = "disabled (bake.tail_estimate = false)";
  }
  delta_multiple = Texture4D();  // no longer needed: free it before the stored table is integrated
  last_density = Texture4D();
  // The density is stored on density_sampler's texels (bakeContents).
  tables.multiple_density = std::move(density_sum);
  if (last_order < 2) {
    tables.multiple_scattering = Texture4D(s.r, s.mu, s.mu_s, s.nu);
  } else {
    tables.multiple_scattering = stage.run("multiple_scattering", 0, rows_4d, [&] {
      return computeMultipleScatteringTable(ctx, optical_depth, density_sampler, tables.multiple_density, stored_shape,
                                            kStoredRaySegments);
    });
    // Prefiltered before the sky irradiance below sums it, as the lookups blend it.
    prefilterAcrossSunBelowHorizon(tables.multiple_scattering, scatteringTexelMuS(sampler.domain(), s));
    prefilterAcrossAltitude(tables.multiple_scattering);
    // The sky irradiance of orders 2 and up, from the stored table: the same
    // light the sky radiance lookups give (its orders' own tables are coarser).
    const OrderRadiance stored{2, tables.single_rayleigh, tables.single_mie, tables.multiple_scattering, stored_shape};
    const Texture2D multiple_irradiance = stage.run("indirect_irradiance", 0, config.sizes.irradiance_r, [&] {
      return computeIndirectIrradianceTable(ctx, optical_depth, stored);
    });
    addScaled(tables.irradiance.texels, multiple_irradiance.texels, Spectrum(1.0f));
  }

  if (scene) {
    scene->last = Texture4D();  // no longer needed: free it before the stored tables are built
    const ScatteringSizes& ss = scene->sampler.scatteringSizes();
    // Single and multiple scattering each advance once per (r, mu) row of the scene's tables.
    stage.run("scene_tables", 0, 2 * static_cast<size_t>(ss.r) * ss.mu, [&] {
      narrowTablesToScene(scene->ctx, density_sampler, optical_depth, stored_shape, std::move(scene->sum), tables);
    });
  }

  // Every lookup blends linearly across r, and the twilight lookups blend
  // the multiple scattering across the sun below the horizon geometrically
  // where it is steep: the 4D tables store what those blends need
  // (altitude_prefilter.h, sun_prefilter.h). Only now: while the orders iterate,
  // each table is read at its own r texels (the next order's density) or
  // along rays by an interpolation of its own (the density, geometric in r
  // for a sun below the horizon). The whole domain's multiple scattering
  // and single scattering already are, for the sky irradiance; a scene's
  // tables were computed again on its own texels.
  prefilterAcrossAltitude(tables.multiple_density);
  if (scene || !single_prefiltered) {
    prefilterAcrossAltitude(tables.single_rayleigh);
    prefilterAcrossAltitude(tables.single_mie);
  }
  if (scene) {
    const TableSampler& stored = scene->sampler;
    prefilterAcrossSunBelowHorizon(tables.multiple_scattering,
                                   scatteringTexelMuS(stored.domain(), stored.scatteringSizes()));
    prefilterAcrossAltitude(tables.multiple_scattering);
  }
  // The parts the file leaves out (no Mie scattering, outputs the scene does
  // not use): computed where later orders needed them, not kept.
  out.file.contents = bakeContents(config);
  settleStoredTables(out.file.contents, tables);

  report.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.cpu_seconds = processCpuSeconds() - cpu_start;
  report.peak_memory_mib = peakMemoryMiB();

  out.file.config_toml = configToToml(config);
  out.file.orders_computed = static_cast<int>(report.orders.size());
  out.file.report_json = report.toJson();
  return out;
}

}  // namespace skybake
