// The options that choose a reference, shared by the commands that compute
// one (validate, reference): its query set, its paths per query and its cache.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace skybake::cli {

// Adds --queries, --reference-samples and --cache-dir, bound to the given
// values (whose initial values are the defaults --help shows).
void addReferenceOptions(CLI::App& command, std::string& queries, int& reference_samples, std::string& cache_dir);

}  // namespace skybake::cli
