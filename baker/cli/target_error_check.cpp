#include "baker/cli/target_error_check.h"

#include <algorithm>

#include "baker/validation/lane_group_validation.h"
#include "baker/validation/validation.h"
#include "baker/validation/validation_queries.h"
#include "runtime/sky.h"

namespace skybake {
namespace {

// The worst channel's RMS and reference noise of one band, in percent.
void worstOf(const ErrorReport& report, const std::string& band, double& rms_percent, double& noise_percent,
             int& count) {
  const ErrorRow* row = report.find("sky_radiance", band);
  if (row == nullptr) return;
  for (const ErrorStats& s : row->channels) {
    rms_percent = std::max(rms_percent, 100.0 * s.rms);
    noise_percent = std::max(noise_percent, 100.0 * s.reference_standard_error);
    count = std::max(count, s.count);
  }
}

}  // namespace

nlohmann::ordered_json TargetErrorCheck::toJson() const {
  if (!checked) return {{"checked", false}, {"reason", reason}};
  return {{"checked", true},
          {"query_set", "quick"},
          {"reference_paths", reference_paths},
          {"day_queries", queries},
          {"day_sky_radiance_rms_percent", day_percent},
          {"low_sun_sky_radiance_rms_percent", low_sun_percent},
          {"reference_noise_percent", reference_noise_percent},
          {"reference_seconds", reference_seconds}};
}

TargetErrorCheck checkTargetError(const BakeFile& bake, int reference_paths, ProgressSink& progress) {
  TargetErrorCheck check;
  if (bake.contents.atmosphere.storesCieXyz()) {
    check.reason = "a colour bake's reference needs its config's wavelengths: `skybake validate --colour-config`";
    return check;
  }
  const Sky sky(bake);
  const AtmosphereParameters& a = sky.atmosphere();
  std::string left_out;
  const QuerySet queries = queriesAnsweredBy(sky, querySetNamed("quick", a.bottom_radius_m, a.top_radius_m), left_out);
  ReferenceSettings settings;
  settings.paths = reference_paths;
  const std::vector<ReferenceValues> references = computeLaneGroupReferences(sky, queries, settings, progress);
  const ErrorReport report =
      compareLaneGroupsWithReference(sky, queries, references, evaluateLaneGroups(sky, queries), settings.paths);
  double unused_noise = 0.0;
  int unused_count = 0;
  worstOf(report, "day", check.day_percent, check.reference_noise_percent, check.queries);
  worstOf(report, "low_sun", check.low_sun_percent, unused_noise, unused_count);
  check.reference_seconds = referenceTotals(references).seconds;
  check.reference_paths = reference_paths;
  check.checked = check.queries > 0;
  if (!check.checked) check.reason = "no day-band sky radiance query of the quick set lies inside the scene's ranges";
  return check;
}

}  // namespace skybake
