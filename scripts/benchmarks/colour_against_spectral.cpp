// How far a colour bake's colours are from a spectral bake of the same
// atmosphere and sizes with many more wavelengths (41 for the figures in
// docs/COLOUR_BAKES.md): both bakes' lookups at the same queries, the
// spectral bake's channels converted to X, Y, Z as `skybake render` and
// `validate` convert them, compared as `validate --colour-config` compares
// a bake with the colour reference (luminance error, CIEDE2000 at the
// reference's lightness), by sun band and for the low sun's last degree.
// What remains is the colour path's own error: both bakes share tables of
// the same sizes and the same interpolation.
//
// The queries: cameras at 0, 1, 10 and 30 km; suns every 10 deg from 0 to
// 80, every degree to 89, every 0.1 deg to 90 and every 0.5 deg to 96 (civil
// twilight); views every 10 deg in zenith from 0 to 180 plus 85, 88, 89,
// 89.5, 90.5, 91, 92 and 95 near the horizon, at azimuths 0, 45, 90, 135 and
// 180 deg from the sun.
//
// Usage: colour_against_spectral COLOUR.exr SPECTRAL.exr
// (COLOUR.exr may be a bake of wavelengths too: its channels are converted
// to X, Y, Z the same way.)
#include <cstdio>
#include <exception>
#include <vector>

#include "baker/validation/colour_error.h"
#include "baker/validation/lane_group_validation.h"
#include "baker/validation/validation_queries.h"
#include "data_formats/error.h"
#include "runtime/sky.h"

namespace {

using namespace skybake;

QuerySet colourQueries() {
  std::vector<double> suns;
  for (int s = 0; s <= 80; s += 10) suns.push_back(s);
  for (int s = 81; s <= 89; ++s) suns.push_back(s);
  for (int s = 1; s <= 10; ++s) suns.push_back(89.0 + 0.1 * s);
  for (int s = 1; s <= 12; ++s) suns.push_back(90.0 + 0.5 * s);
  std::vector<double> views;
  for (int v = 0; v <= 180; v += 10) views.push_back(v);
  for (double v : {85.0, 88.0, 89.0, 89.5, 90.5, 91.0, 92.0, 95.0}) views.push_back(v);
  QuerySet set;
  set.name = "colour";
  for (double altitude : {0.0, 1000.0, 10000.0, 30000.0}) {
    for (double sun : suns) {
      for (double view : views) {
        for (double azimuth : {0.0, 45.0, 90.0, 135.0, 180.0})
          set.radiance.push_back({altitude, sun, view, azimuth, 0.0});
      }
      set.irradiance.push_back({altitude, sun});
    }
  }
  return set;
}

// The spectral bake's X, Y, Z as a reference without noise.
ColourReferenceValues asReference(const MethodXyz& xyz) {
  ColourReferenceValues r;
  auto convert = [](const std::vector<colour::Xyz>& values, std::vector<CachedReference>& out) {
    for (const colour::Xyz& c : values) {
      CachedReference v;
      v.value = SpectrumD(c.x, c.y, c.z, 0.0);
      v.standard_error = SpectrumD(0.0);
      v.transmittance = SpectrumD(0.0);
      out.push_back(v);
    }
  };
  convert(xyz.radiance, r.radiance);
  convert(xyz.irradiance, r.irradiance);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s COLOUR.exr SPECTRAL.exr\n", argv[0]);
    return 2;
  }
  try {
    const Sky colour_bake = Sky::load(argv[1]);
    const Sky spectral_bake = Sky::load(argv[2]);
    if (spectral_bake.atmosphere().storesCieXyz()) {
      std::fprintf(stderr, "%s must be a bake of wavelengths\n", argv[2]);
      return 2;
    }
    const QuerySet queries = colourQueries();
    const MethodXyz colour = bakeXyz(colour_bake, evaluateLaneGroups(colour_bake, queries));
    const MethodXyz spectral = bakeXyz(spectral_bake, evaluateLaneGroups(spectral_bake, queries));
    const ColourErrorReport report =
        compareColourWithReference(colour_bake.atmosphere(), queries, asReference(spectral), colour, 0);
    std::printf("%s against %s (%zu radiance and %zu irradiance queries)\n%s", argv[1], argv[2],
                queries.radiance.size(), queries.irradiance.size(), report.table().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
