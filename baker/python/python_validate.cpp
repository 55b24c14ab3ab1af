// skybake._skybake.validate: a bake's error against the independent
// reference, as `skybake validate` measures it, returned as the report's
// JSON object (the same keys as `validate --json`, a spectral bake's
// figures per wavelength from a reference per lane group; with colour_config, its
// "colour" object too: luminance and CIEDE2000 per sun band against the
// colour reference, docs/COLOUR.md). The reference cache is
// shared with the command line; unlike it, this writes no report sidecar.
#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "baker/cli/terminal_progress.h"
#include "baker/python/python_bindings.h"
#include "baker/stages/openmp_threads.h"
#include "baker/validation/colour_error.h"
#include "baker/validation/colour_reference.h"
#include "baker/validation/lane_group_validation.h"
#include "baker/validation/validation.h"
#include "baker/validation/validation_queries.h"
#include "data_formats/error.h"
#include "runtime/sky.h"

namespace py = pybind11;

namespace skybake::python {
namespace {

py::object validate(const std::string& bake_path, const std::string& queries_name, int reference_samples,
                    const std::string& cache_dir, bool no_cache, const py::object& threads_argument,
                    const std::string& colour_config) {
  const int threads = threadCountArgument(threads_argument);
  std::string report_json;
  {
    py::gil_scoped_release release;
    const ScopedOpenMpThreads thread_count(threads);
    const Sky sky = Sky::load(bake_path);
    const AtmosphereParameters& a = sky.atmosphere();
    std::optional<ColourReferenceAtmospheres> colour;
    if (!colour_config.empty()) {
      requireConfigOfBake(colour_config, a, sky.contents().lane_groups);
      colour = colourReferenceAtmospheresFromFile(colour_config);
    }
    std::string left_out;
    const QuerySet queries =
        queriesAnsweredBy(sky, querySetNamed(queries_name, a.bottom_radius_m, a.top_radius_m), left_out);
    const ReferenceSettings settings = referenceSettings(reference_samples, cache_dir, no_cache);
    cli::TerminalProgress progress;
    // A spectral bake's lane groups each against their own reference, as the command line does.
    const std::vector<ReferenceValues> references = computeLaneGroupReferences(sky, queries, settings, progress);
    const std::vector<MethodValues> bakes = evaluateLaneGroups(sky, queries);
    nlohmann::ordered_json j = compareLaneGroupsWithReference(sky, queries, references, bakes, settings.paths).toJson();
    if (colour) {
      const ColourReferenceValues colour_reference = computeColourReference(*colour, queries, settings, progress);
      j["colour"] = validateColour(sky, queries, references, colour_reference, bakes, settings.paths).toJson();
      j["colour"]["config"] = colour_config;
    }
    if (sky.laneGroupCount() > 1) j["lane_groups"] = laneGroupsJson(sky, references);
    j["bake_file"] = bake_path;
    j["lookup_seconds_per_ray"] = secondsPerRay(bakes);
    if (!left_out.empty()) j["left_out"] = left_out;
    report_json = j.dump();
  }
  return py::module_::import("json").attr("loads")(report_json);
}

}  // namespace

void registerValidate(py::module_& m) {
  m.def("validate", &validate, py::arg("bake"), py::arg("queries") = "standard",
        py::arg("reference_samples") = ReferenceSettings{}.paths, py::arg("cache_dir") = "",
        py::arg("no_cache") = false, py::arg("threads") = 0, py::arg("colour_config") = "");
}

}  // namespace skybake::python
