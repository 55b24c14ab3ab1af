// skybake._skybake.bake: a config into a bake file, as `skybake bake` makes
// it. The config is a TOML file's path or a dict in the config schema
// (data_formats/CONFIG.md); a dict becomes a TOML table read by the same
// reader as a file, so it is validated with the same messages, naming the
// key's path after "config dict" where a file's would name its line. Progress goes to a Python callback progress(stage,
// fraction), or to the command line's bar on stderr.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "baker/bake/bake.h"
#include "baker/bake/bake_policy.h"
#include "baker/cli/bake_memory_estimate.h"
#include "baker/cli/option_checks.h"
#include "baker/cli/terminal_progress.h"
#include "baker/python/python_bindings.h"
#include "data_formats/atomic_file.h"
#include "data_formats/config/config.h"
#include "data_formats/config/config_table.h"
#include "data_formats/config/toml_text_check.h"
#include "data_formats/error.h"
#include "data_formats/input_file.h"
#include "data_formats/terminal_text.h"

namespace py = pybind11;

namespace skybake::python {
namespace {

constexpr const char* kDictSource = "config dict";

void badDictValue(const std::string& key, const std::string& why) {
  throw Error(ErrorKind::BadInput, std::string(kDictSource) + ": " + key + ": " + why);
}

// A Python value being converted: the containers (dicts, lists, tuples)
// that hold it, outermost first, so that a container holding itself is
// found and nesting is refused at the config's own limit before it
// recurses deeper (a dict nested 100000 levels would overflow the stack).
struct DictPath {
  std::vector<const PyObject*> containers;
  void enter(const py::handle& v, const std::string& key) {
    if (std::find(containers.begin(), containers.end(), v.ptr()) != containers.end()) {
      badDictValue(key, "contains itself (a dict or list that holds itself cannot be a config)");
    }
    if (containers.size() >= static_cast<size_t>(kMaxTomlNesting)) {
      badDictValue(key, "nested deeper than a config can be (" + std::to_string(kMaxTomlNesting) + " levels)");
    }
    containers.push_back(v.ptr());
  }
  void leave() { containers.pop_back(); }
};

toml::table tableFromDict(const py::dict& d, const std::string& prefix, DictPath& path);

// A Python int as a TOML integer; `key` names it in messages.
int64_t integerOf(const py::handle& v, const std::string& key) {
  int overflow = 0;
  const long long value = PyLong_AsLongLongAndOverflow(v.ptr(), &overflow);
  if (overflow != 0) badDictValue(key, "the integer " + shownText(std::string(py::str(v))) + " is too large");
  return value;
}

// A Python value as a TOML value; `key` names it in messages.
void insertValue(toml::table& t, const std::string& name, const py::handle& v, const std::string& key, DictPath& path) {
  if (py::isinstance<py::bool_>(v)) {
    t.insert_or_assign(name, v.cast<bool>());
    return;
  }
  if (py::isinstance<py::int_>(v)) {
    t.insert_or_assign(name, integerOf(v, key));
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
    path.enter(v, key);
    t.insert_or_assign(name, tableFromDict(v.cast<py::dict>(), key + ".", path));
    path.leave();
    return;
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    path.enter(v, key);
    toml::array array;
    size_t i = 0;
    for (const py::handle& item : v) {
      const std::string item_key = key + "[" + std::to_string(i++) + "]";
      toml::table holder;
      insertValue(holder, "x", item, item_key, path);
      array.push_back(std::move(*holder.get("x")));
    }
    t.insert_or_assign(name, std::move(array));
    path.leave();
    return;
  }
  // numpy arrays and scalars: as the lists and numbers tolist() gives.
  if (py::hasattr(v, "tolist") && py::hasattr(v, "dtype")) {
    insertValue(t, name, v.attr("tolist")(), key, path);
    return;
  }
  // Other numbers (fractions, decimals): through float().
  if (py::hasattr(v, "__float__")) {
    PyObject* number = PyNumber_Float(v.ptr());
    if (number == nullptr) {
      PyErr_Clear();
      badDictValue(key, "a " + std::string(py::str(v.get_type().attr("__name__"))) + " that float() refuses");
    }
    t.insert_or_assign(name, PyFloat_AsDouble(number));
    Py_DECREF(number);
    return;
  }
  badDictValue(key, "a " + std::string(py::str(v.get_type().attr("__name__"))) +
                        " is not a TOML value (use bool, int, float, str, list or dict)");
}

toml::table tableFromDict(const py::dict& d, const std::string& prefix, DictPath& path) {
  toml::table t;
  for (const auto& [k, v] : d) {
    if (!py::isinstance<py::str>(k)) {
      badDictValue(prefix + shownText(std::string(py::str(k))), "keys must be strings");
    }
    const std::string name = k.cast<std::string>();
    insertValue(t, name, v, prefix + shownText(name), path);
  }
  return t;
}

// A config dict as a TOML table, every value checked (DictPath).
toml::table tableOfDict(const py::dict& d) {
  DictPath path;
  path.enter(d, "(the dict)");
  return tableFromDict(d, "", path);
}

// orders=: None (the config's), "auto", or a whole number of orders, checked
// as the command line's --orders. A Python int of any size is checked by
// its decimal text, so one too large for C++ is refused like any other.
void applyOrders(const py::object& orders, const std::string& source, BakeConfig& config) {
  if (orders.is_none()) return;
  const bool text = py::isinstance<py::str>(orders);
  if (!text && (!py::isinstance<py::int_>(orders) || py::isinstance<py::bool_>(orders))) {
    throw Error(ErrorKind::BadInput, "orders: a " + std::string(py::str(orders.get_type().attr("__name__"))) +
                                         " is not a number of orders (use 'auto' or an int)");
  }
  const std::string choice = py::str(orders).cast<std::string>();
  cli::applyOrdersChoice("orders", shownText(choice), config);
  validateConfig(config, source + " (with orders=" + choice + ")");
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

py::object bake(const py::object& config_source, const std::string& output, const py::object& threads_argument,
                const py::object& orders, bool reproducible, const py::object& progress) {
  const int threads = threadCountArgument(threads_argument);
  BakeConfig config;
  std::string source;
  if (py::isinstance<py::dict>(config_source)) {
    source = kDictSource;
    config = parseConfigTable(tableOfDict(config_source.cast<py::dict>()), source);
  } else {
    source = py::str(config_source).cast<std::string>();
    requireNoNulInPath(source);
    config = loadConfigFile(source);
  }
  applyOrders(orders, source, config);
  // The output may replace neither the config nor a spectrum file it names.
  requireWritableOutput(output, config.input_files);
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
