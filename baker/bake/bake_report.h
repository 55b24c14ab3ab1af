// What a bake reports about itself: its stages' timings, what each order
// added, how the number of orders was decided, and the tail estimate. Stored
// as JSON in the file's header and in the sidecar.
#pragma once

#include <string>
#include <vector>

#include "data_formats/spectra/spectrum.h"

namespace skybake {

struct StageTiming {
  std::string stage;  // transmittance, direct_irradiance, single_scattering, ...
  int order;          // the scattering order the stage produced (0: not order-specific)
  double seconds;
};

// How much each order contributed: the mean over all texels of its radiance
// (W m^-2 sr^-1 nm^-1) and of the sky irradiance it produced (W m^-2 nm^-1),
// per channel. Orders must contribute less and less for a bake to converge.
struct OrderContribution {
  int order;
  Spectrum mean_radiance;
  Spectrum mean_irradiance;  // 0 for the last order (nothing reflects it yet)
};

// The orders after the last computed one, estimated as a series per (altitude,
// sun) slice of the scattering table (baker/bake/slice_tail.h): each later
// order is a ratio times the one before, the ratio relaxing from the slice's
// last one toward `ratio`, the table's (per channel, from the last two
// orders' mean radiance; by day the two agree and the series is the geometric
// ratio / (1 - ratio) times the last order). Applied only where that is
// sound: at least 3 orders and a table ratio in (0, kMaxTailRatio).
struct TailEstimate {
  bool applied = false;
  Spectrum ratio{0.0f};
  std::string reason;  // why it was or was not applied
};

// How the number of orders was decided: fixed by the config, or computed
// until the last order's share of the total fell below the tolerance.
struct OrdersDecision {
  bool automatic = false;
  bool converged = false;  // automatic only: the tolerance was met
  double tolerance = 0.0;  // automatic only
  int cap = 0;             // automatic only: bake.max_orders
  // The last order's share of the total, worst channel, in the (altitude,
  // sun) slice of the scattering table where it is largest (what automatic
  // orders compare with the tolerance), and where that slice is.
  float last_order_share = 0;
  double worst_altitude_m = 0.0;
  double worst_sun_zenith_deg = 0.0;
  // The same share of the whole table's mean radiance (daylight dominates it).
  float mean_last_order_share = 0;
};

// What one order added at each wavelength of a spectral bake, in channel
// order (OrderContribution, wider than a Spectrum).
struct WavelengthOrderContribution {
  int order;
  std::vector<float> mean_radiance;
  std::vector<float> mean_irradiance;
};

struct BakeReport {
  int threads = 1;
  // Colour and spectral bakes: the passes of the order loop (one per group
  // of at most 4 wavelengths); 0 for an ordinary bake, which runs it once.
  int passes = 0;
  // A spectral bake of several passes: what each order added per
  // wavelength, and the tail ratio per wavelength (`orders` and
  // tail.ratio, 4 lanes wide, are then empty and 0).
  std::vector<WavelengthOrderContribution> wavelength_orders;
  std::vector<float> wavelength_tail_ratio;
  OrdersDecision orders_decision;
  TailEstimate tail;
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;
  double peak_memory_mib = 0.0;
  std::vector<StageTiming> stages;
  std::vector<OrderContribution> orders;

  // Wall time summed over stages with this name, all orders.
  double stageSeconds(const std::string& stage) const;
  // With `with_run_facts` false, times, threads and memory are left out: what
  // remains depends only on the config, so identical configs give identical
  // files whatever the machine or thread count.
  std::string toJson(bool with_run_facts = true) const;
};

}  // namespace skybake
