#include "baker/stress/stress_cases.h"

#include "baker/stress/invariants.h"

namespace skybake {
namespace {

// Table sizes. Quick: those of the unit-test bakes, so the whole matrix bakes
// in seconds on two cores; full: twice the resolution on the angular axes.
// The transmittance table is the full one in both: lookups with the sun
// below the horizon integrate single scattering over it (Sky), and at 64 x 16
// a grazing ray from the top of the mie_g_0 case dimmed 5.2 % per 1e-4 rad of
// view angle where the reference dims 3.5 %.
TextureSizes stressSizes(bool quick) {
  TextureSizes s;
  s.transmittance_mu = 128;
  s.transmittance_r = 32;
  s.irradiance_mu_s = quick ? 16 : 32;
  s.irradiance_r = 8;
  s.scattering_r = quick ? 8 : 16;
  s.scattering_mu = quick ? 32 : 64;
  s.scattering_mu_s = quick ? 8 : 16;
  s.scattering_nu = 4;
  return s;
}

// Orders for the optically thick cases: automatic, to 1e-3 of the total, with
// a cap that keeps the run short. A case that reaches the cap unconverged is
// reported as such (it is still checked: every partial sum must be finite).
void useAutomaticOrders(BakeConfig& c, bool quick) {
  c.bake.auto_orders = true;
  c.bake.order_tolerance = 1e-3;
  c.bake.max_orders = quick ? 16 : 32;
}

void scaleDensityHeights(DensityProfile& profile, double factor) {
  for (DensityLayer& l : profile) {
    l.width_m *= factor;
    l.exp_scale /= factor;
    l.linear_term /= factor;
  }
}

// Squeezes the atmosphere's vertical extent by `factor` (< 1) keeping every
// vertical optical depth: heights and widths scale by factor, coefficients by
// 1 / factor.
void scaleAtmosphereThickness(AtmosphereParameters& a, double factor) {
  a.top_radius_m = a.bottom_radius_m + factor * (a.top_radius_m - a.bottom_radius_m);
  const float coefficient_scale = static_cast<float>(1.0 / factor);
  a.rayleigh_scattering *= coefficient_scale;
  a.mie_scattering *= coefficient_scale;
  a.mie_extinction *= coefficient_scale;
  a.absorption_extinction *= coefficient_scale;
  scaleDensityHeights(a.rayleigh_density, factor);
  scaleDensityHeights(a.mie_density, factor);
  scaleDensityHeights(a.absorption_density, factor);
}

constexpr double kEarthAtmosphereThickness_m = 60000.0;
const std::string kOrdersDecrease = "orders decrease";  // the name checkOrdersDecrease gives

}  // namespace

std::vector<StressCase> stressCases(bool quick) {
  BakeConfig earth = builtinEarthConfig();
  earth.sizes = stressSizes(quick);
  earth.bake.orders = 4;
  std::vector<StressCase> cases;
  auto add = [&](const std::string& name, const std::string& description, BakeConfig c) {
    c.name = "stress_" + name;
    cases.push_back({name, description, std::move(c), {}, {}});
  };
  // The last case added breaks `invariant` at the quick sizes only.
  auto failsInQuickRun = [&](const std::string& invariant, const std::string& reason) {
    if (!quick) return;
    cases.back().known_failures = {invariant};
    cases.back().known_failure_reason = reason;
  };

  add("earth", "the built-in Earth (baseline)", earth);
  {
    // Earth's Mie extinction is 4.44e-6 m^-1 at the ground: x100 gives a
    // meteorological visibility 3.912 / 4.44e-4 m^-1 = 8.8 km, x1000 0.9 km.
    BakeConfig c = earth;
    c.atmosphere.mie_scattering *= 1000.0f;
    c.atmosphere.mie_extinction *= 1000.0f;
    useAutomaticOrders(c, quick);
    add("thick_haze", "Mie x1000: visibility ~0.9 km, vertical Mie optical depth ~5", c);
    failsInQuickRun(
        kOrdersDecrease,
        "at the quick sizes an order after the fifth can exceed the one before by up to 0.4 % before the orders "
        "decay at ~0.93 per order; at the full sizes every order decreases, so the coarse tables are the likely cause");
  }
  {
    // Rayleigh x1000 with a 16 km scale height (Venus's): vertical optical
    // depth 93 (680 nm) to 530 (440 nm). The top at 160 km (10 scale heights)
    // cuts off exp(-10) of it, under 0.03.
    BakeConfig c = earth;
    AtmosphereParameters& a = c.atmosphere;
    constexpr double kVenusScaleHeight_m = 16000.0;
    a.top_radius_m = a.bottom_radius_m + 10.0 * kVenusScaleHeight_m;
    a.rayleigh_scattering *= 1000.0f;
    a.rayleigh_density = {{0.0, 1.0, -1.0 / kVenusScaleHeight_m, 0.0, 0.0}};
    useAutomaticOrders(c, quick);
    add("venus_like", "Rayleigh x1000, scale height 16 km: vertical optical depth 93 to 530", c);
  }
  {
    BakeConfig c = earth;
    c.atmosphere.rayleigh_scattering = Spectrum(0.0f);
    c.atmosphere.mie_scattering = Spectrum(0.0f);
    add("absorption_only", "no scattering; Mie extinction and ozone absorb", c);
  }
  {
    BakeConfig c = earth;
    AtmosphereParameters& a = c.atmosphere;
    a.rayleigh_scattering = a.mie_scattering = a.mie_extinction = a.absorption_extinction = Spectrum(0.0f);
    add("no_atmosphere", "every coefficient 0", c);
  }
  {
    BakeConfig c = earth;
    AtmosphereParameters& a = c.atmosphere;
    a.mie_extinction = a.mie_scattering;
    a.absorption_extinction = Spectrum(0.0f);
    for (int ch = 0; ch < a.channelCount(); ++ch) a.ground_albedo[ch] = 1.0f;
    useAutomaticOrders(c, quick);
    add("conservative", "no absorption anywhere, ground albedo 1", c);
    cases.back().check_energy_budget = true;
    failsInQuickRun(
        kEnergyBudgetCloses,
        "at the quick sizes the bake makes light: (in - out) / in = -1.5 %, -3.0 %, -5.7 % at 680, 550, 440 nm. The "
        "scattering table's 8 mu_s texels leave one interval from mu_s 0.36 to 1 (sun zenith 69 to 0 deg); "
        "interpolated linearly in the texture coordinate, light proportional to mu_s (the lit ground's, most of "
        "what leaves a planet of albedo 1) comes out up to 24 % high mid-interval, 12 % over the sphere. With 16 "
        "mu_s and 16 r texels the imbalance is -0.3 to -0.5 %, at the full sizes -0.4 to -1.5 %");
  }
  for (const auto& [name, g] : {std::pair{"mie_g_0.99", 0.99}, {"mie_g_0", 0.0}, {"mie_g_-0.9", -0.9}}) {
    BakeConfig c = earth;
    c.atmosphere.mie_phase_g = g;
    add(name, "Mie phase asymmetry g = " + std::to_string(g).substr(0, 5), c);
  }
  {
    BakeConfig c = earth;
    scaleAtmosphereThickness(c.atmosphere, 1000.0 / kEarthAtmosphereThickness_m);
    add("shell_1km", "Earth's optical depths in a 1 km thick atmosphere", c);
  }
  {
    BakeConfig c = earth;
    c.atmosphere.bottom_radius_m = 10000.0;
    c.atmosphere.top_radius_m = 10000.0 + kEarthAtmosphereThickness_m;
    scaleAtmosphereThickness(c.atmosphere, 1000.0 / kEarthAtmosphereThickness_m);
    add("tiny_planet", "radius 10 km, atmosphere 1 km thick with Earth's optical depths", c);
  }
  {
    BakeConfig c = earth;
    c.atmosphere.bottom_radius_m = 1e8;
    c.atmosphere.top_radius_m = 1e8 + kEarthAtmosphereThickness_m;
    add("huge_planet", "radius 1e8 m (nearly flat), Earth's atmosphere", c);
  }
  {
    BakeConfig c = builtinMarsConfig();
    c.sizes = stressSizes(quick);
    add("mars", "data_formats/presets/mars.toml", c);
  }
  {
    BakeConfig c = earth;
    c.atmosphere.sun_angular_radius_rad = 0.0;
    add("sun_point", "sun angular radius 0 (a point sun)", c);
  }
  {
    BakeConfig c = earth;
    c.atmosphere.sun_angular_radius_rad = 0.1;
    add("sun_0.1rad", "sun angular radius 0.1 rad (21 times the Sun's)", c);
  }
  {
    // Every ray toward the ground is integrated at lookup, not read from
    // the tables: the runtime path the other cases do not take.
    BakeConfig c = earth;
    c.scene_ranges.views_below_horizon = false;
    c.sizes.iteration =
        std::array<int, 4>{c.sizes.scattering_r, c.sizes.scattering_mu, c.sizes.scattering_mu_s, c.sizes.scattering_nu};
    add("sky_views_only", "Earth without views below the horizon (scene.views_below_horizon = false)", c);
  }
  return cases;
}

}  // namespace skybake
