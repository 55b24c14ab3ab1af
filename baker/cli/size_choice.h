// Table sizes for a target error (`skybake bake --target-error`): the
// cheapest size of the measured sweep of the built-in Earth
// (docs/ERROR_VS_TIME.md) whose error meets it. Only measured sizes are
// offered: between them the error does not follow a smooth curve (0.85x
// measured 1.32 % at low sun where a log-log fit between 0.75x and 1x
// predicted 0.97 %), because where the mu_s texels fall near the horizon
// matters as much as how many there are.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "data_formats/config/atmosphere_parameters.h"

namespace skybake {

// One measured point of the sweep: sizes scaled by `scale`, and the sky
// radiance's RMS error of the worst channel in the day and low-sun bands.
struct SweepPoint {
  double scale;
  double day_percent;
  double low_sun_percent;
  double bake_seconds;  // 2 threads
};

// The points the choice interpolates, from `bash scripts/sweep.sh`.
const std::vector<SweepPoint>& earthSweep();

struct SizeChoice {
  double scale = 1.0;                   // of every default size
  double predicted_percent = 0.0;       // the sweep's worst of day and low sun, as validate reports
  double predicted_bake_seconds = 0.0;  // the sweep's, 2 threads
  TextureSizes sizes;
};

// The worst channel of the day and low-sun figures.
double worstPercent(const SweepPoint& p);

// The cheapest swept size whose error is at most `target_percent`; nullopt
// when even the largest misses it.
std::optional<SizeChoice> chooseSizesForError(double target_percent);

// The sweep's point as a choice: its sizes, error and time.
SizeChoice sizeChoiceAt(const SweepPoint& p);

// The sweep's next size above `scale`; nullopt at the largest.
std::optional<SizeChoice> nextLargerSweptSizes(double scale);

// The default sizes times `scale`, rounded; at least 2 per axis, the
// scattering mu even and at least 4 (as scripts/sweep/make_config.py).
TextureSizes scaledDefaultSizes(double scale);

}  // namespace skybake
