// The default Earth bake (the built-in Earth: 41 x 16 sun and view-sun texels, 6 orders, float), timed whole,
// with per-stage times as counters. Run through scripts/bench_bake.sh.
#include <benchmark/benchmark.h>

#include "baker/bake/bake.h"
#include "data_formats/config/config.h"

namespace {

void BM_DefaultEarthBake(benchmark::State& state) {
  const skybake::BakeConfig config = skybake::builtinEarthConfig();
  skybake::SilentProgress silent;
  skybake::BakeReport last;
  for (auto _ : state) {
    skybake::BakeOutput bake = skybake::bakeAtmosphere(config, static_cast<int>(state.range(0)), silent);
    benchmark::DoNotOptimize(bake.file.tables.multiple_scattering.texels.data());
    last = bake.report;
  }
  for (const char* stage : {"transmittance", "direct_irradiance", "single_scattering", "density_kernel",
                            "scattering_density", "indirect_irradiance", "order_radiance", "multiple_scattering"}) {
    state.counters[std::string(stage) + "_s"] = last.stageSeconds(stage);
  }
  state.counters["threads"] = last.threads;
}

}  // namespace

// One bake per repetition; the repetitions give the median.
BENCHMARK(BM_DefaultEarthBake)->ArgName("threads")->Arg(0)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

BENCHMARK_MAIN();
