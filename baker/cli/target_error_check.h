// `skybake bake --target-error`: the chosen sizes confirmed on the bake
// itself. Its sky radiance is validated on the quick query set (inside the
// scene's ranges) against the reference, which the cache keeps, so that
// the target holds for this atmosphere and not only for the built-in Earth
// the sizes were swept on.
#pragma once

#include <nlohmann/json.hpp>

#include "baker/stages/progress.h"
#include "data_formats/bake_file/bake_file.h"

namespace skybake {

struct TargetErrorCheck {
  bool checked = false;  // false: the bake cannot be checked so (a colour bake); `reason` says why
  std::string reason;
  int queries = 0;           // day-band sky radiance queries compared
  double day_percent = 0.0;  // RMS relative error, worst channel
  double low_sun_percent = 0.0;
  double reference_noise_percent = 0.0;  // the reference's own, day band, worst channel
  double reference_seconds = 0.0;        // spent computing what the cache lacked
  int reference_paths = 0;
  bool meets(double target_percent) const { return checked && day_percent <= target_percent; }
  nlohmann::ordered_json toJson() const;
};

// `reference_paths` Monte Carlo paths per query (ReferenceSettings).
TargetErrorCheck checkTargetError(const BakeFile& bake, int reference_paths, ProgressSink& progress);

}  // namespace skybake
