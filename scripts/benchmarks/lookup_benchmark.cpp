// Sky-radiance lookups per second on one core: scalar calls and the batch
// entry point, over view directions spread over the whole sphere from a
// camera 1 km up, with the sun 30 deg from the zenith (day: table lookups
// only) and 95 deg (twilight: single scattering integrated along each ray).
// The bake comes from $SKYBAKE_BAKE (scripts/bench_lookup.sh); on a
// spectral bake only BM_ChannelSkyRadiance runs (the others take 4 lanes).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <random>

#include "runtime/sky.h"

namespace {

const skybake::Sky& benchSky() {
  static const skybake::Sky sky = [] {
    const char* path = std::getenv("SKYBAKE_BAKE");
    return skybake::Sky::load(path != nullptr ? path : "out/earth.exr");
  }();
  return sky;
}

struct Directions {
  std::vector<float> x, y, z;
};

// Uniform on the sphere, fixed seed.
Directions randomDirections(size_t count) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  Directions d;
  for (size_t i = 0; i < count; ++i) {
    const float z = 2.0f * uniform(rng) - 1.0f;
    const float phi = 6.2831853f * uniform(rng);
    const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
    d.x.push_back(s * std::cos(phi));
    d.y.push_back(s * std::sin(phi));
    d.z.push_back(z);
  }
  return d;
}

constexpr size_t kRays = 1 << 16;
// The sun at the benchmark's argument, in degrees from the zenith.
glm::dvec3 sunAt(const benchmark::State& state) {
  const double zenith = skybake::radiansFromDegrees(static_cast<double>(state.range(0)));
  return {std::sin(zenith), 0.0, std::cos(zenith)};
}

// One scalar lookup per iteration, cycling through the directions.
template <typename Lookup>
void timeScalarLookups(benchmark::State& state, const Lookup& lookup) {
  const skybake::Sky& sky = benchSky();
  const Directions d = randomDirections(kRays);
  const glm::dvec3 camera(0.0, 0.0, sky.atmosphere().bottom_radius_m + 1000.0);
  const glm::dvec3 sun = sunAt(state);
  size_t i = 0;
  for (auto _ : state) {
    const auto v = lookup(sky, camera, glm::dvec3(d.x[i], d.y[i], d.z[i]), sun);
    benchmark::DoNotOptimize(v);
    i = (i + 1) % kRays;
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_SkyRadianceScalar(benchmark::State& state) {
  timeScalarLookups(state, [](const skybake::Sky& sky, const glm::dvec3& camera, const glm::dvec3& view,
                              const glm::dvec3& sun) { return sky.skyRadiance(camera, view, sun); });
}
BENCHMARK(BM_SkyRadianceScalar)->ArgName("sun_zenith_deg")->Arg(30)->Arg(95);

// Every channel of any bake, a spectral one's lane groups included
// (Sky::everyChannel): one skyRadiance per lane group and the joining.
void BM_ChannelSkyRadiance(benchmark::State& state) {
  timeScalarLookups(
      state, [](const skybake::Sky& sky, const glm::dvec3& camera, const glm::dvec3& view, const glm::dvec3& sun) {
        return sky.everyChannel([&](const skybake::Sky& group) { return group.skyRadiance(camera, view, sun); });
      });
  state.counters["channels"] = benchSky().channelCount();
}
BENCHMARK(BM_ChannelSkyRadiance)->ArgName("sun_zenith_deg")->Arg(30)->Arg(95);

void BM_SkyRadianceBatch(benchmark::State& state) {
  const skybake::Sky& sky = benchSky();
  const Directions d = randomDirections(kRays);
  const glm::dvec3 camera(0.0, 0.0, sky.atmosphere().bottom_radius_m + 1000.0);
  const glm::dvec3 sun = sunAt(state);
  std::vector<float> radiance[3], transmittance[3];
  skybake::SpectrumBatch r{}, t{};
  for (int c = 0; c < 3; ++c) {
    radiance[c].resize(kRays);
    transmittance[c].resize(kRays);
    r.channel[c] = radiance[c].data();
    t.channel[c] = transmittance[c].data();
  }
  for (auto _ : state) {
    sky.skyRadianceBatch(camera, sun, {d.x.data(), d.y.data(), d.z.data(), kRays}, r, t);
    benchmark::DoNotOptimize(radiance[0].data());
  }
  state.SetItemsProcessed(state.iterations() * kRays);
}
BENCHMARK(BM_SkyRadianceBatch)->ArgName("sun_zenith_deg")->Arg(30)->Arg(95)->Unit(benchmark::kMillisecond);

}  // namespace

// Eclipse lookups (docs/ECLIPSES.md): the camera on the ground at the centre
// of a total eclipse's umbra, sun 40 deg high behind a 0.28 deg moon. With
// the argument 1 the camera's skylight share is computed once and passed
// (as skybake render does), with 0 at every lookup.
void BM_SkyRadianceEclipse(benchmark::State& state) {
  const skybake::Sky& sky = benchSky();
  const Directions d = randomDirections(kRays);
  const glm::dvec3 camera(0.0, 0.0, sky.atmosphere().bottom_radius_m);
  const double zenith = skybake::radiansFromDegrees(50.0);
  const glm::dvec3 sun(std::sin(zenith), 0.0, std::cos(zenith));
  const skybake::Moon moon = skybake::Moon::seenFrom(camera, sun, skybake::radiansFromDegrees(0.28));
  const bool shared_skylight = state.range(0) != 0;
  const skybake::Spectrum skylight = sky.eclipseSkylight(camera, {sun, moon});
  size_t i = 0;
  for (auto _ : state) {
    const glm::dvec3 view(d.x[i], d.y[i], d.z[i]);
    const auto v = shared_skylight ? sky.skyRadiance(camera, view, {sun, moon, skylight})
                                   : sky.skyRadiance(camera, view, {sun, moon});
    benchmark::DoNotOptimize(v);
    i = (i + 1) % kRays;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SkyRadianceEclipse)->ArgName("shared_skylight")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
