#include "baker/cli/reference_options.h"

#include "baker/cli/option_checks.h"
#include "baker/validation/validation.h"

namespace skybake::cli {

void addReferenceOptions(CLI::App& command, std::string& queries, int& reference_samples, std::string& cache_dir) {
  command
      .add_option("--queries", queries,
                  "standard (docs/QUERIES.md), quick (a small subset) or a CSV with the columns of "
                  "'lookup radiance'.")
      ->capture_default_str();
  requireWholeIn(command.add_option("--reference-samples", reference_samples, "Monte Carlo paths per reference query.")
                     ->capture_default_str(),
                 1, kMaxReferencePaths);
  command.add_option("--cache-dir", cache_dir,
                     "Reference cache directory (default $SKYBAKE_CACHE_DIR, $XDG_CACHE_HOME/skybake or "
                     "~/.cache/skybake).");
}

}  // namespace skybake::cli
