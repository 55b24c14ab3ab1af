// Concurrent Sky lookups: several threads looking up one Sky at once get
// exactly what one thread gets, and (built with the tsan preset) the thread
// sanitizer sees no data race. The runtime alone, no test framework, so the
// sanitizer instruments all the code the threads run.
// Usage: concurrent_lookups_test BAKE.exr
#include <cstdio>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "runtime/sky.h"

namespace {

using skybake::Spectrum;

constexpr int kThreads = 4;
constexpr int kQueries = 200;

struct Result {
  Spectrum sky, sky_transmittance, to_point, irradiance_sky, irradiance_sun, transmittance;
  bool operator==(const Result&) const = default;
};

// A spread of cameras, views and suns, day and twilight, rays to the ground
// and to space.
Result lookUp(const skybake::Sky& sky, int i) {
  const double bottom = sky.atmosphere().bottom_radius_m;
  const glm::dvec3 camera(0.0, 0.0, bottom + 37.0 * (i % 50) * (i % 7 == 0 ? 1000.0 : 10.0));
  const double view_zenith = 0.0157 * (i % 200), view_azimuth = 0.31 * i;
  const glm::dvec3 view(std::sin(view_zenith) * std::cos(view_azimuth), std::sin(view_zenith) * std::sin(view_azimuth),
                        std::cos(view_zenith));
  const double sun_zenith = 0.0178 * (i % 100);
  const glm::dvec3 sun(std::sin(sun_zenith), 0.0, std::cos(sun_zenith));
  Result r;
  const skybake::RadianceAndTransmittance s = sky.skyRadiance(camera, view, sun);
  r.sky = s.radiance;
  r.sky_transmittance = s.transmittance;
  if (sky.outputs().radiance_to_points) r.to_point = sky.radianceToPoint(camera, camera + view * 5000.0, sun).radiance;
  if (sky.outputs().ground_irradiance) {
    const skybake::SunAndSkyIrradiance e = sky.irradiance(camera, glm::normalize(camera), sun);
    r.irradiance_sky = e.sky;
    r.irradiance_sun = e.sun;
  }
  r.transmittance = sky.transmittance(camera, camera + view * 20000.0);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: concurrent_lookups_test BAKE.exr\n");
    return 2;
  }
  const skybake::Sky sky = skybake::Sky::load(argv[1]);
  std::vector<Result> expected;
  for (int i = 0; i < kQueries; ++i) expected.push_back(lookUp(sky, i));
  std::vector<int> mismatches(kThreads, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      // Each thread starts elsewhere, so that different lookups overlap.
      for (int k = 0; k < kQueries; ++k) {
        const int i = (k + t * kQueries / kThreads) % kQueries;
        if (!(lookUp(sky, i) == expected[i])) ++mismatches[t];
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  int failed = 0;
  for (int t = 0; t < kThreads; ++t) {
    if (mismatches[t] > 0) std::printf("thread %d: %d lookups differ from one thread's\n", t, mismatches[t]);
    failed += mismatches[t] > 0;
  }
  std::printf("%d passed, %d failed\n", kThreads - failed, failed);
  return failed == 0 ? 0 : 1;
}
