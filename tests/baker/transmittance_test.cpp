// Transmittance against closed forms and an independent quadrature.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/bake/bake.h"
#include "baker/numerics/optical_depth_integral.h"
#include "baker/stages/optical_depth_table.h"
#include "data_formats/config/config.h"

namespace skybake {
namespace {

// Integral of exp(-h / H) from 0 to thickness.
double exponentialColumn(double scale_height, double thickness) {
  return scale_height * (1.0 - std::exp(-thickness / scale_height));
}

// Integral over [h0, h1] of clamp(a h + c, 0, 1), exactly: split where the
// line crosses 0 and 1, then integrate each straight piece.
double clampedLinearColumn(double a, double c, double h0, double h1) {
  std::vector<double> cuts = {h0, h1};
  for (double level : {0.0, 1.0}) {
    const double h = (level - c) / a;
    if (h > h0 && h < h1) cuts.push_back(h);
  }
  std::sort(cuts.begin(), cuts.end());
  double total = 0.0;
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double mid = 0.5 * (cuts[i] + cuts[i + 1]);
    const double value = a * mid + c;
    const double width = cuts[i + 1] - cuts[i];
    if (value >= 1.0)
      total += width;
    else if (value > 0.0)
      total += width * value;  // linear: midpoint rule is exact
  }
  return total;
}

// Closed-form vertical optical depth of the built-in Earth from the ground.
SpectrumD earthVerticalOpticalDepth(const AtmosphereParameters& a) {
  const double thickness = a.top_radius_m - a.bottom_radius_m;
  const double rayleigh = exponentialColumn(8000.0, thickness);
  const double mie = exponentialColumn(1.0 / 8.333e-4, thickness);
  const double ozone =
      clampedLinearColumn(6.667e-5, -0.6667, 0.0, 25000.0) + clampedLinearColumn(-6.667e-5, 2.6667, 25000.0, thickness);
  // The tent is 15 km in area to 1e-4: the test's own sanity check.
  EXPECT_NEAR(ozone, 15000.0, 2.0);
  return SpectrumD(a.rayleigh_scattering) * rayleigh + SpectrumD(a.mie_extinction) * mie +
         SpectrumD(a.absorption_extinction) * ozone;
}

// Independent quadrature: composite Simpson with 200 000 intervals, densities
// evaluated from the config without the baker's helpers. On Earth's 60 km
// column the step is 0.3 m (2.5e-4 Mie scale heights); Simpson's error there
// is far below 1e-9 relative except at the ozone kinks, where a kink inside
// one 0.3 m step costs at most ~1e-9 of the 15 km tent.
double independentOpticalDepth(const AtmosphereParameters& a, int channel, double r, double mu) {
  const double length = -r * mu + std::sqrt(r * r * (mu * mu - 1.0) + a.top_radius_m * a.top_radius_m);
  const int n = 200000;
  const double h = length / n;
  auto extinction = [&](double t) {
    const double altitude = std::sqrt(t * t + 2.0 * r * mu * t + r * r) - a.bottom_radius_m;
    const double rayleigh = std::exp(-altitude / 8000.0);
    const double mie = std::exp(-altitude * 8.333e-4);
    const double ozone = altitude < 25000.0 ? std::clamp(6.667e-5 * altitude - 0.6667, 0.0, 1.0)
                                            : std::clamp(-6.667e-5 * altitude + 2.6667, 0.0, 1.0);
    return a.rayleigh_scattering[channel] * rayleigh + a.mie_extinction[channel] * mie +
           a.absorption_extinction[channel] * ozone;
  };
  double sum = extinction(0.0) + extinction(length);
  for (int i = 1; i < n; ++i) sum += extinction(i * h) * (i % 2 ? 4.0 : 2.0);
  return sum * h / 3.0;
}

// The bound for transmittance: 0.1 % relative.
constexpr double kTransmittanceTolerance = 1e-3;

TEST(Transmittance, VerticalFromGroundMatchesClosedForm) {
  const BakeConfig config = builtinEarthConfig();
  const AtmosphereParameters& a = config.atmosphere;
  const SpectrumD expected = earthVerticalOpticalDepth(a);
  const SpectrumD quadrature = integrateOpticalDepthToTop(AtmosphereMedia(a), a.bottom_radius_m, 1.0);

  SilentProgress silent;
  const TableSampler sampler(AtmosphereDomain::fromParameters(a), config.sizes);
  const Texture2D table = computeOpticalDepthTable({a, sampler, silent});
  // Texel (mu 0, r 0) sits exactly on r = bottom, mu = 1.
  const Spectrum tabulated = table.at(0, 0);
  for (int c = 0; c < 3; ++c) {
    const double t_expected = std::exp(-expected[c]);
    EXPECT_NEAR(std::exp(-quadrature[c]) / t_expected, 1.0, kTransmittanceTolerance) << "channel " << c;
    EXPECT_NEAR(std::exp(-tabulated[c]) / t_expected, 1.0, kTransmittanceTolerance) << "channel " << c;
  }
}

TEST(Transmittance, SlantedRaysMatchIndependentQuadrature) {
  const BakeConfig config = builtinEarthConfig();
  const AtmosphereParameters& a = config.atmosphere;
  const AtmosphereMedia media(a);
  for (double altitude : {0.0, 1000.0, 12000.0, 35000.0}) {
    const double r = a.bottom_radius_m + altitude;
    const double horizon_mu = -std::sqrt(1.0 - (a.bottom_radius_m / r) * (a.bottom_radius_m / r));
    for (double mu : {0.9, 0.5, 0.2, 0.05, 0.0, horizon_mu + 0.01}) {
      const SpectrumD depth = integrateOpticalDepthToTop(media, r, mu);
      for (int c = 0; c < 3; ++c) {
        const double reference = independentOpticalDepth(a, c, r, mu);
        EXPECT_NEAR(std::exp(-depth[c]) / std::exp(-reference), 1.0, kTransmittanceTolerance)
            << "altitude " << altitude << " mu " << mu << " channel " << c;
        // Tighter: the optical depth itself to 1e-5 relative.
        EXPECT_NEAR(depth[c] / reference, 1.0, 1e-5);
      }
    }
  }
}

TEST(Transmittance, TableLookupsBetweenTexelsStayWithinTolerance) {
  // Bilinear interpolation in the Bruneton parameterization: optical depth
  // between texels is smooth in (x_mu, x_r), so lookups above the horizon
  // stay within the tolerance on transmittance at the default 256 x 64.
  const BakeConfig config = builtinEarthConfig();
  const AtmosphereParameters& a = config.atmosphere;
  SilentProgress silent;
  const TableSampler sampler(AtmosphereDomain::fromParameters(a), config.sizes);
  const Texture2D table = computeOpticalDepthTable({a, sampler, silent});
  for (double altitude : {0.0, 500.0, 3333.0, 12000.0, 47000.0}) {
    const double r = a.bottom_radius_m + altitude;
    for (double mu : {0.97, 0.61, 0.33, 0.17, 0.08}) {
      const Spectrum looked_up = sampler.opticalDepthToTop(table, r, mu);
      for (int c = 0; c < 3; ++c) {
        const double reference = independentOpticalDepth(a, c, r, mu);
        EXPECT_NEAR(std::exp(-looked_up[c]) / std::exp(-reference), 1.0, kTransmittanceTolerance)
            << "altitude " << altitude << " mu " << mu << " channel " << c;
      }
    }
  }
}

}  // namespace
}  // namespace skybake
