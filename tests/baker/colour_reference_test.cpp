// The colour reference (baker/validation/colour_reference.h): its XYZ is the
// 41-wavelength XYZ of the per-wavelength references, exactly for the
// deterministic part and within the Monte Carlo error for the paths; a
// config that is not the bake's is refused; its cache has a directory of
// its own. And colour error's normalisation: a luminance error alone gives
// the CIEDE2000 lightness difference it should.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "baker/reference/reference_solver.h"
#include "baker/validation/colour_error.h"
#include "baker/validation/colour_reference.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"
#include "data_formats/queries/local_frame.h"
#include "runtime/colour/cielab.h"
#include "runtime/colour/spectral_to_xyz.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

// Earth's atmosphere with every per-wavelength key a spectrum over 380 to
// 780 nm, written inline (no files): a sun that rises toward the blue, a
// reddish ground, Rayleigh's law, hazy Mie by Angstrom's law, ozone.
constexpr const char* kColourConfig = R"(
[channels]
wavelengths_nm = [680, 550, 440]
[planet]
bottom_radius_m = 6360000.0
top_radius_m = 6420000.0
ground_albedo = { wavelengths_nm = [380, 780], values = [0.05, 0.3] }
[sun]
irradiance = { wavelengths_nm = [380, 480, 780], values = [1.1, 2.0, 1.3] }
[rayleigh]
scattering = { at_nm = 550, value = 13.558e-6, exponent = 4 }
density = [{ exp_term = 1.0, exp_scale = -1.25e-4 }]
[mie]
scattering = { at_nm = 550, value = 3.996e-6, angstrom_exponent = 1.3 }
extinction = { at_nm = 550, value = 4.44e-6, angstrom_exponent = 1.3 }
phase_g = 0.8
density = [{ exp_term = 1.0, exp_scale = -8.333e-4 }]
[absorption]
extinction = { wavelengths_nm = [380, 600, 780], values = [1e-8, 2.0e-6, 2e-7] }
density = [{ width_m = 25000.0, linear_term = 6.667e-5, constant_term = -0.6667 },
           { linear_term = -6.667e-5, constant_term = 2.6667 }]
)";

ColourReferenceAtmospheres colourAtmospheres() { return colourReferenceAtmospheres(kColourConfig, "test.toml", {}); }

// A day sky ray and a ray toward the ground at low sun, from 1 km.
std::vector<ReferenceRay> testRays(const AtmosphereParameters& a) {
  const glm::dvec3 camera = cameraAtAltitude(a.bottom_radius_m, 1000.0);
  return {{camera, directionFromZenithAzimuthDeg(70.0, 90.0), directionFromZenithAzimuthDeg(40.0, 0.0), 0.0},
          {camera, directionFromZenithAzimuthDeg(120.0, 180.0), directionFromZenithAzimuthDeg(84.0, 0.0), 0.0}};
}

// The XYZ of the per-wavelength references: each group's 4-channel
// reference through the 41 wavelengths' colour-matching weights. Its
// standard error adds each group's channels' errors linearly (they share
// paths: at most perfectly correlated) and the groups' in quadrature.
ReferenceEstimate xyzOfPerWavelengthReferences(const ColourReferenceAtmospheres& colour, const ReferenceRay& ray,
                                               int paths_per_group, uint64_t seed) {
  const colour::SpectralToXyz to_xyz(colour.wavelengths_nm);
  ReferenceEstimate total{SpectrumD(0.0), SpectrumD(0.0)};
  SpectrumD variance(0.0);
  for (size_t g = 0; g < colour.groups.size(); ++g) {
    const ReferenceEstimate e = ReferenceSolver(colour.groups[g]).radiance(ray, paths_per_group, seed + g);
    SpectrumD error(0.0);
    for (int lane = 0; lane < colour.groups[g].channelCount(); ++lane) {
      // Group g's lane holds wavelength g + lane x (number of groups).
      const colour::Xyz& w = to_xyz.weight(static_cast<int>(g) + lane * kColourWavelengthGroups);
      total.value += SpectrumD(w.x, w.y, w.z, 0.0) * e.value[lane];
      error += SpectrumD(w.x, w.y, w.z, 0.0) * e.standard_error[lane];
    }
    variance += error * error;
  }
  total.standard_error = glm::sqrt(variance);
  return total;
}

TEST(ColourReference, GroupsCoverTheVisibleWavelengthsOnce) {
  const ColourReferenceAtmospheres colour = colourAtmospheres();
  ASSERT_EQ(colour.wavelengths_nm.size(), 41u);
  EXPECT_EQ(colour.wavelengths_nm.front(), 380.0);
  EXPECT_EQ(colour.wavelengths_nm.back(), 780.0);
  std::vector<int> seen(41, 0);
  for (const AtmosphereParameters& group : colour.groups) {
    for (double w : group.wavelengths_nm) ++seen[static_cast<size_t>(std::lround((w - 380.0) / 10.0))];
  }
  for (int k = 0; k < 41; ++k) EXPECT_EQ(seen[k], 1) << colour.wavelengths_nm[k];
}

// Without paths the reference is single scattering alone, deterministic:
// the colour reference must be the per-wavelength XYZ to rounding (sums in
// another order: 1e-12 relative).
TEST(ColourReference, SingleScatteringIsTheXyzOfEachWavelength) {
  const ColourReferenceAtmospheres colour = colourAtmospheres();
  for (const ReferenceRay& ray : testRays(colour.groups.front())) {
    const ColourEstimate c = colourRadianceReference(colour, ray, 0, 7);
    const ReferenceEstimate s = xyzOfPerWavelengthReferences(colour, ray, 0, 7);
    for (int i = 0; i < 3; ++i) {
      ASSERT_GT(s.value[i], 0.0);
      EXPECT_NEAR(c.value[i] / s.value[i], 1.0, 1e-12) << i;
      EXPECT_EQ(c.standard_error[i], 0.0);
      EXPECT_EQ(c.half_difference[i], 0.0);
    }
  }
}

// With paths, two independent estimates of the same XYZ: the colour
// reference (paths shared among the groups) and the per-wavelength
// references with 4 times the paths per group. They must agree within 5
// combined standard errors (the standard errors themselves come from 16
// replicates, +-18 %: 5 sigma of a t distribution with 15 degrees of
// freedom is exceeded with probability 2e-4). The multiple scattering they
// estimate is 10 to 40 % of these rays' radiance and its noise 0.3 to 1 %,
// so a wrong weight or a group left out would be tens of standard errors off.
TEST(ColourReference, PathsAgreeWithPerWavelengthReferencesWithinStandardError) {
  const ColourReferenceAtmospheres colour = colourAtmospheres();
  constexpr int kPaths = 8192;
  for (const ReferenceRay& ray : testRays(colour.groups.front())) {
    const ColourEstimate c = colourRadianceReference(colour, ray, kPaths, 11);
    const ReferenceEstimate s = xyzOfPerWavelengthReferences(colour, ray, 8 * colourGroupHalfPaths(kPaths), 1234);
    const ColourEstimate single = colourRadianceReference(colour, ray, 0, 11);
    for (int i = 0; i < 3; ++i) {
      const double combined = std::hypot(c.standard_error[i], s.standard_error[i]);
      EXPECT_GT(c.standard_error[i], 0.0);
      EXPECT_LT(std::abs(c.value[i] - s.value[i]), 5.0 * combined) << i << ": " << c.value[i] << " vs " << s.value[i];
      // The test has power: the paths' share is many standard errors.
      EXPECT_GT(c.value[i] - single.value[i], 20.0 * combined) << i;
    }
  }
}

// The reference's CIEDE2000 error as its halves measure it
// (referenceColourError of each estimate's half_difference) against the
// spread of independent colour references of one query (their CIEDE2000
// from their mean, n - 1 degrees of freedom): both are RMS of 24 draws of
// one error's distribution, each known to about +-15 % (a chi variable of
// one to three degrees of freedom), so they agree within a factor of 1.6
// either way (64 estimates of 4096 paths: 0.265 and 0.277). Modelling X, Y
// and Z's errors as independent instead overstates it about twice (their
// shared paths move mostly lightness), full correlation understates it
// about twice. Few paths per replicate (2048 paths in all: 5 each) spread
// the halves' figure wider.
TEST(ColourReference, HalvesMeasureTheSpreadOfIndependentEstimates) {
  const ColourReferenceAtmospheres colour = colourAtmospheres();
  const ReferenceRay ray = testRays(colour.groups.front())[0];
  constexpr int kEstimates = 24, kPaths = 4096;
  std::vector<ColourEstimate> estimates;
  SpectrumD mean(0.0);
  for (int i = 0; i < kEstimates; ++i) {
    estimates.push_back(colourRadianceReference(colour, ray, kPaths, 100 + i));
    mean += estimates.back().value / static_cast<double>(kEstimates);
  }
  auto xyz = [](const SpectrumD& s) { return colour::Xyz{s.x, s.y, s.z}; };
  double spread2 = 0.0, halves2 = 0.0;
  for (const ColourEstimate& e : estimates) {
    const double spread = colourDifference(xyz(e.value), xyz(mean));
    const double halves = referenceColourError(xyz(e.value), xyz(e.half_difference));
    spread2 += spread * spread;
    halves2 += halves * halves;
  }
  const double measured = std::sqrt(spread2 / (kEstimates - 1)), from_halves = std::sqrt(halves2 / kEstimates);
  EXPECT_GT(from_halves, 0.0);
  EXPECT_LT(measured / from_halves, 1.6) << measured << " vs " << from_halves;
  EXPECT_GT(measured / from_halves, 1.0 / 1.6) << measured << " vs " << from_halves;
}

TEST(ColourReference, RefusesAConfigThatIsNotTheBakes) {
  const fs::path dir = fs::temp_directory_path() / ("skybake_colour_reference_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "c.toml") << kColourConfig;
  const AtmosphereParameters bake = parseConfig(kColourConfig, "test.toml").atmosphere;
  EXPECT_NO_THROW(requireConfigOfBake(dir / "c.toml", bake));
  AtmosphereParameters other = bake;
  other.mie_phase_g = 0.7;
  EXPECT_THROW(requireConfigOfBake(dir / "c.toml", other), Error);
  fs::remove_all(dir);
}

TEST(ColourReference, CacheHasADirectoryOfItsOwn) {
  const ColourReferenceAtmospheres colour = colourAtmospheres();
  const fs::path dir = fs::temp_directory_path() / ("skybake_colour_cache_test_" + std::to_string(::getpid()));
  const ReferenceCache colour_cache(dir, colour.groups, 64);
  const ReferenceCache spectral_cache(dir, colour.groups.front(), 64);
  EXPECT_EQ(colour_cache.directory().filename().string().rfind("colour-reference-", 0), 0u);
  EXPECT_NE(colour_cache.directory(), spectral_cache.directory());
  EXPECT_NE(colour_cache.directory(), ReferenceCache(dir, colour.groups, 128).directory());
  fs::remove_all(dir);
}

// The normalisation: a grey that differs from its reference only by a
// factor of luminance differs in CIELAB lightness alone (a* = b* = 0 under
// the white), by CIELAB's slope at L* = 50: dL* = 116 / 3 f(Y) dY / Y with
// f(Y) = 66 / 116 (and S_L = 1 there). The result does not depend on the
// reference's absolute brightness. (A coloured patch scaled alike also
// changes chroma, by C* dY / 3Y: CIELAB's cube root.)
TEST(ColourError, LuminanceErrorAloneIsALightnessDifference) {
  const colour::Xyz white = colour::srgbWhiteXyz();
  const double relative_error = 1e-3;
  auto grey = [&](double y) { return colour::Xyz{white.x * y, white.y * y, white.z * y}; };
  const double expected = 116.0 / 3.0 * (66.0 / 116.0) * relative_error;
  // Linearised: the next term is about relative_error / 3 of it.
  EXPECT_NEAR(colourDifference(grey(0.25 * (1 + relative_error)), grey(0.25)), expected, expected * relative_error);
  EXPECT_NEAR(colourDifference(grey(2.5e-4 * (1 + relative_error)), grey(2.5e-4)), expected, expected * relative_error);
  EXPECT_EQ(colourDifference(grey(0.25), grey(0.25)), 0.0);
  // Chromaticity counts: a bluer patch of the same luminance differs.
  EXPECT_GT(colourDifference({white.x * 0.2, 0.2, white.z * 0.22}, grey(0.2)), 1.0);
}

// The low sun's last degree is a row of its own besides the low sun's: a
// query at 89.5 deg counts in both, one at 85 deg only in the low sun's,
// and the rows come day, low sun, last degree, twilight.
TEST(ColourError, LastDegreeOfTheLowSunIsReportedApart) {
  AtmosphereParameters a = colourAtmospheres().groups.front();
  QuerySet queries;
  for (double sun : {30.0, 85.0, 89.5, 92.0}) queries.radiance.push_back({0.0, sun, 60.0, 90.0, 0.0});
  ColourReferenceValues reference;
  MethodXyz method;
  for (size_t i = 0; i < queries.radiance.size(); ++i) {
    CachedReference r;
    r.value = SpectrumD(5.0, 5.0, 5.0, 0.0);
    r.standard_error = SpectrumD(0.0);
    reference.radiance.push_back(r);
    // 1 % too bright at 89.5 deg, exact elsewhere.
    const double y = queries.radiance[i].sun_zenith_deg == 89.5 ? 5.05 : 5.0;
    method.radiance.push_back({5.0, y, 5.0});
  }
  const ColourErrorReport report = compareColourWithReference(a, queries, reference, method, 0);
  std::vector<std::string> bands;
  for (const ColourErrorRow& row : report.rows) bands.push_back(row.band);
  EXPECT_EQ(bands, (std::vector<std::string>{"day", "low_sun", kLastDegreeBand, "twilight"}));
  const ColourErrorRow* low = report.find("sky_radiance", "low_sun");
  const ColourErrorRow* last = report.find("sky_radiance", kLastDegreeBand);
  ASSERT_NE(low, nullptr);
  ASSERT_NE(last, nullptr);
  EXPECT_EQ(low->stats.count, 2);
  EXPECT_EQ(last->stats.count, 1);
  EXPECT_NEAR(last->stats.luminance_rms, 0.01, 1e-9);
  EXPECT_NEAR(low->stats.luminance_rms, 0.01 / std::sqrt(2.0), 1e-9);
  EXPECT_NE(report.table().find(kLastDegreeBand), std::string::npos);
}

}  // namespace
}  // namespace skybake
