#include "baker/cli/reference_options.h"

#include "baker/cli/option_checks.h"
#include "baker/validation/validation.h"

namespace skybake::cli {

void addReferenceOptions(CLI::App& command, std::string& queries, int& reference_samples, std::string& cache_dir) {
  command
      .add_option("--queries", queries,
                  "standard (docs/QUERIES.md), quick (a small subset), eclipse (solar eclipses) or a CSV "
                  "with the columns of 'lookup radiance' (and optionally moon_separation_deg, "
                  "moon_angular_radius_deg), or with those of 'lookup irradiance' alone (altitude_m, "
                  "sun_zenith_deg: sky irradiance).")
      ->capture_default_str();
  requireWholeIn(command
                     .add_option("--reference-samples", reference_samples,
                                 "Monte Carlo paths per reference query, twice that for a ray to a point with the "
                                 "sun below the camera's horizon (0: single scattering alone, the reference's "
                                 "deterministic part, to compare a bake of one order with).")
                     ->capture_default_str(),
                 0, kMaxReferencePaths);
  command.add_option("--cache-dir", cache_dir,
                     "Reference cache directory (default $SKYBAKE_CACHE_DIR, $XDG_CACHE_HOME/skybake or "
                     "~/.cache/skybake).");
}

}  // namespace skybake::cli
