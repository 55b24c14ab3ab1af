// skybake._skybake.bake: a config into a bake file, as `skybake bake` makes
// it. The config is a TOML file's path or a dict in the config schema
// (data_formats/CONFIG.md); a dict is written as TOML and read by the same
// parser, so it is validated with the same messages (its source named
// "config dict"). Progress goes to a Python callback progress(stage,
// fraction), or to the command line's bar on stderr.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>

#include <toml++/toml.h>

#include "baker/bake/bake.h"
#include "baker/bake/bake_policy.h"
#include "baker/cli/bake_memory_estimate.h"
#include "baker/cli/terminal_progress.h"
#include "baker/python/python_bindings.h"
#include "data_formats/config.h"
#include "data_formats/error.h"

namespace py = pybind11;

namespace skybake::python {
namespace {

constexpr const char* kDictSource = "config dict";

void badDictValue(const std::string& key, const std::string& why) {
  throw Error(ErrorKind::BadInput, std::string(kDictSource) + ": " + key + ": " + why);
}

toml::table tableFromDict(const py::dict& d, const std::string& prefix);

// A Python value as a TOML value; `key` names it in messages.
void insertValue(toml::table& t, const std::string& name, const py::handle& v, const std::string& key) {
  if (py::isinstance<py::bool_>(v)) {
    t.insert_or_assign(name, v.cast<bool>());
    return;
  }
  if (py::isinstance<py::int_>(v)) {
    t.insert_or_assign(name, v.cast<int64_t>());
    return;
  }
  if (py::isinstance<py::float_>(v)) {
    t.insert_or_assign(name, v.cast<double>());
    return;
  }
  if (py::isinstance<py::str>(v)) {
    t.insert_or_assign(name, v.cast<std::string>());
    return;
  }
  if (py::isinstance<py::dict>(v)) {
    t.insert_or_assign(name, tableFromDict(v.cast<py::dict>(), key + "."));
    return;
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    toml::array array;
    size_t i = 0;
    for (const py::handle& item : v) {
      const std::string item_key = key + "[" + std::to_string(i++) + "]";
      toml::table holder;
      insertValue(holder, "x", item, item_key);
      array.push_back(std::move(*holder.get("x")));
    }
    t.insert_or_assign(name, std::move(array));
    return;
  }
  // numpy scalars and other numbers: through float().
  if (py::hasattr(v, "__float__")) {
    t.insert_or_assign(name, v.cast<double>());
    return;
  }
  badDictValue(key, "a " + std::string(py::str(v.get_type().attr("__name__"))) +
                        " is not a TOML value (use bool, int, float, str, list or dict)");
}

toml::table tableFromDict(const py::dict& d, const std::string& prefix) {
  toml::table t;
  for (const auto& [k, v] : d) {
    if (!py::isinstance<py::str>(k)) badDictValue(prefix + std::string(py::str(k)), "keys must be strings");
    const std::string name = k.cast<std::string>();
    insertValue(t, name, v, prefix + name);
  }
  return t;
}

// The bake's progress as calls of a Python function: each stage at 0, at
// every tenth of its work and at 1. Worker threads take the GIL only for
// those calls; an exception from the function is kept and raised after the
// bake, and the function is not called again.
class PythonProgress final : public ProgressSink {
 public:
  explicit PythonProgress(py::function callback) : callback_(std::move(callback)) {}
  void beginStage(const std::string& name, size_t work_units) override {
    stage_ = name;
    total_ = std::max<size_t>(work_units, 1);
    done_ = 0;
    next_tenth_ = 1;
    call(0.0);
  }
  void advance(size_t units) override {
    const size_t done = done_.fetch_add(units) + units;
    size_t tenth = next_tenth_.load();
    while (tenth < 10 && done * 10 >= tenth * total_) {
      if (next_tenth_.compare_exchange_weak(tenth, tenth + 1)) {
        call(tenth / 10.0);
        ++tenth;
      }
    }
  }
  void endStage(double) override { call(1.0); }
  void raiseIfFailed() {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  void call(double fraction) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_) return;
    py::gil_scoped_acquire gil;
    try {
      callback_(stage_, fraction);
    } catch (...) {
      error_ = std::current_exception();
    }
  }
  py::function callback_;
  std::string stage_;
  size_t total_ = 1;
  std::atomic<size_t> done_{0};
  std::atomic<size_t> next_tenth_{1};
  std::mutex mutex_;
  std::exception_ptr error_;
};

py::object bake(const py::object& config_source, const std::string& output, int threads, std::optional<int> orders,
                bool reproducible, const py::object& progress) {
  BakeConfig config;
  std::string source;
  if (py::isinstance<py::dict>(config_source)) {
    std::ostringstream text;
    text << tableFromDict(config_source.cast<py::dict>(), "");
    source = kDictSource;
    config = parseConfig(text.str(), source);
  } else {
    source = py::str(config_source).cast<std::string>();
    config = loadConfigFile(source);
  }
  if (orders) {
    config.bake.orders = *orders;
    config.bake.auto_orders = false;
    validateConfig(config, source + " (with orders=" + std::to_string(*orders) + ")");
  }
  if (threads < 0) throw Error(ErrorKind::BadInput, "threads = " + std::to_string(threads) + ": must be >= 0");
  config = settledBakeConfig(config);
  requireMemoryForBake(config, source);
  std::optional<PythonProgress> python_progress;
  std::optional<cli::TerminalProgress> terminal_progress;
  std::optional<SilentProgress> silent;
  ProgressSink* sink = nullptr;
  if (!progress.is_none()) {
    sink = &python_progress.emplace(progress.cast<py::function>());
  } else if (py::module_::import("sys").attr("stderr").attr("isatty")().cast<bool>()) {
    sink = &terminal_progress.emplace();
  } else {
    sink = &silent.emplace();
  }
  std::string report;
  {
    py::gil_scoped_release release;
    BakeOutput out = bakeAtmosphere(config, threads, *sink);
    setStoredReport(out, !reproducible);
    setBakeFileWriteThreads(out.report.threads);
    writeBakeFile(output, out.file);
    report = out.report.toJson(!reproducible);
  }
  if (python_progress) python_progress->raiseIfFailed();
  return py::module_::import("json").attr("loads")(report);
}

}  // namespace

void registerBake(py::module_& m) {
  m.def("bake", &bake, py::arg("config"), py::arg("output"), py::arg("threads") = 0, py::arg("orders") = py::none(),
        py::arg("reproducible") = false, py::arg("progress") = py::none());
}

}  // namespace skybake::python
