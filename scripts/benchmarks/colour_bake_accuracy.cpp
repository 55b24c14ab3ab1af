// How far a colour bake's lookups are from the spectral truth of the same
// wavelengths: the config's colour bake (channels.store = "cie_xyz") against
// its wavelengths baked as ordinary passes of at most 4, whose lookups are
// summed into X, Y, Z with the same colour-matching weights. Prints one
// Markdown table row per lookup kind and sun zenith angle: the relative
// error of Y (luminance) and the largest chromaticity (x, y) difference.
// docs/COLOUR_BAKES.md has the figures and the command.
//
// Usage: colour_bake_accuracy CONFIG.toml [THREADS]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "baker/bake/bake.h"
#include "baker/bake/bake_passes.h"
#include "baker/bake/bake_policy.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"
#include "runtime/colour/colour_bake_weights.h"
#include "runtime/sky.h"

namespace {

using namespace skybake;

struct Xyz {
  double x = 0.0, y = 0.0, z = 0.0;
};

// Values below this share of the largest Y of a row's queries are left out
// of the relative errors: the dark ground-facing rays of a bright sky.
constexpr double kDarkShare = 1e-4;

struct Errors {
  std::vector<double> relative_y;
  double chromaticity = 0.0;
  void add(const Xyz& colour, const Xyz& truth) {
    if (!(truth.y > 0.0)) return;
    relative_y.push_back(std::abs(colour.y - truth.y) / truth.y);
    const double sc = colour.x + colour.y + colour.z, st = truth.x + truth.y + truth.z;
    chromaticity =
        std::max({chromaticity, std::abs(colour.x / sc - truth.x / st), std::abs(colour.y / sc - truth.y / st)});
  }
  void print(const char* lookup, double sun_zenith_deg) {
    std::sort(relative_y.begin(), relative_y.end());
    double sum = 0.0;
    for (double e : relative_y) sum += e * e;
    const double rms = relative_y.empty() ? 0.0 : std::sqrt(sum / relative_y.size());
    const double p95 = relative_y.empty() ? 0.0 : relative_y[relative_y.size() * 95 / 100];
    const double max = relative_y.empty() ? 0.0 : relative_y.back();
    std::printf("| %s | %g | %zu | %.3f %% | %.3f %% | %.3f %% | %.5f |\n", lookup, sun_zenith_deg, relative_y.size(),
                100.0 * rms, 100.0 * p95, 100.0 * max, chromaticity);
  }
};

glm::dvec3 direction(double zenith_deg, double azimuth_deg) {
  return directionFromZenithAzimuth(radiansFromDegrees(zenith_deg), radiansFromDegrees(azimuth_deg));
}

class Comparison {
 public:
  Comparison(const BakeConfig& config, int threads) : weights_(settledBakeConfig(config).colour_groups) {
    SilentProgress quiet;
    colour_.emplace_back(bakeAtmosphere(config, threads, quiet).file);
    const BakeConfig settled = settledBakeConfig(config);
    for (size_t g = 0; g < settled.colour_groups.size(); ++g) {
      passes_.emplace_back(bakeAtmosphere(passConfig(settled, g), threads, quiet).file);
    }
  }
  const Sky& colour() const { return colour_[0]; }

  // X, Y, Z of the colour bake's and of the passes' values of one lookup:
  // radiance and irradiance weighted by the colour-matching functions, a
  // transmittance (`sunlight_mean`) by each channel's sunlight shares, the
  // mean the colour bake's effective optical depth stands for.
  template <typename Lookup>
  void both(Lookup&& lookup, bool sunlight_mean, Xyz& colour, Xyz& truth) const {
    const Spectrum c = lookup(colour_[0]);
    colour = {c[0], c[1], c[2]};
    truth = {};
    int i = 0;
    for (const Sky& p : passes_) {
      const Spectrum s = lookup(p);
      for (int l = 0; l < p.channelCount(); ++l, ++i) {
        auto weight = [&](int channel) {
          return sunlight_mean ? weights_.sunlightShare(channel, i) : weights_.colourMatching(channel, i);
        };
        truth.x += weight(0) * s[l];
        truth.y += weight(1) * s[l];
        truth.z += weight(2) * s[l];
      }
    }
  }

 private:
  colour::ColourBakeWeights weights_;
  std::vector<Sky> colour_, passes_;
};

// Every query's X, Y, Z of one lookup, then errors of those bright enough.
template <typename Lookup>
void compareRow(const Comparison& c, const char* name, double sun_zenith_deg, const std::vector<glm::dvec3>& views,
                Lookup&& lookup, bool sunlight_mean = false) {
  std::vector<Xyz> colour(views.size()), truth(views.size());
  double brightest = 0.0;
  for (size_t v = 0; v < views.size(); ++v) {
    c.both([&](const Sky& sky) { return lookup(sky, views[v]); }, sunlight_mean, colour[v], truth[v]);
    brightest = std::max(brightest, truth[v].y);
  }
  Errors e;
  for (size_t v = 0; v < views.size(); ++v) {
    if (truth[v].y > kDarkShare * brightest) e.add(colour[v], truth[v]);
  }
  e.print(name, sun_zenith_deg);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: colour_bake_accuracy CONFIG.toml [THREADS]\n");
    return 2;
  }
  try {
    const BakeConfig config = loadConfigFile(argv[1]);
    if (!config.atmosphere.storesCieXyz()) throwBadInput(std::string(argv[1]) + ": not a colour bake");
    const int threads = argc > 2 ? std::stoi(argv[2]) : 0;
    const Comparison c(config, threads);
    const double bottom = c.colour().atmosphere().bottom_radius_m;
    std::vector<glm::dvec3> views;
    for (double zenith = 0.0; zenith <= 180.0; zenith += 5.0) {
      for (double azimuth = 0.0; azimuth <= 180.0; azimuth += 15.0) views.push_back(direction(zenith, azimuth));
    }
    std::printf("| lookup | sun zenith (deg) | queries | Y RMS | Y p95 | Y max | max chromaticity |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    for (double sun_zenith : {0.0, 30.0, 60.0, 80.0, 88.0, 92.0, 96.0, 100.0, 104.0}) {
      const glm::dvec3 sun = direction(sun_zenith, 0.0);
      const glm::dvec3 ground(0.0, 0.0, bottom + 10.0), high(0.0, 0.0, bottom + 10000.0);
      compareRow(c, "sky radiance, 10 m", sun_zenith, views,
                 [&](const Sky& s, const glm::dvec3& v) { return s.skyRadiance(ground, v, sun).radiance; });
      compareRow(c, "sky radiance, 10 km", sun_zenith, views,
                 [&](const Sky& s, const glm::dvec3& v) { return s.skyRadiance(high, v, sun).radiance; });
      compareRow(c, "radiance to a point 20 km away", sun_zenith, views, [&](const Sky& s, const glm::dvec3& v) {
        return s.radianceToPoint(ground, ground + 20000.0 * v, sun).radiance;
      });
      compareRow(
          c, "transmittance of the view ray", sun_zenith, views,
          [&](const Sky& s, const glm::dvec3& v) { return s.skyRadiance(ground, v, sun).transmittance; }, true);
      compareRow(c, "sun + sky irradiance", sun_zenith, {glm::dvec3(0.0, 0.0, 1.0)},
                 [&](const Sky& s, const glm::dvec3& n) {
                   const SunAndSkyIrradiance e = s.irradiance(ground, n, sun);
                   return e.sun + e.sky;
                 });
    }
  } catch (const Error& e) {
    std::fprintf(stderr, "colour_bake_accuracy: %s\n", e.what());
    return 2;
  }
  return 0;
}
