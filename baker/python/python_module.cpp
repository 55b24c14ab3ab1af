// The compiled part of `import skybake` (skybake._skybake). skybake::Error of
// kind BadInput becomes skybake.BadInput, a ValueError carrying the message
// the command line prints; other kinds become RuntimeError.
#include <pybind11/pybind11.h>

#include <string>

#include "baker/python/python_bindings.h"
#include "baker/stages/openmp_threads.h"
#include "data_formats/error.h"

namespace py = pybind11;

namespace skybake::python {

int threadCountArgument(const py::handle& threads) {
  if (!py::isinstance<py::int_>(threads) || py::isinstance<py::bool_>(threads)) {
    throw Error(ErrorKind::BadInput, "threads: a " + std::string(py::str(threads.get_type().attr("__name__"))) +
                                         " is not a thread count (use an int; 0: all cores)");
  }
  int overflow = 0;
  const long long count = PyLong_AsLongLongAndOverflow(threads.ptr(), &overflow);
  if (overflow != 0) {
    throw Error(ErrorKind::BadInput, "threads = " + std::string(py::str(threads)) + ": must be 0 (all cores) or 1 to " +
                                         std::to_string(kMaxThreadCount));
  }
  requireThreadCount(count);
  return static_cast<int>(count);
}

}  // namespace skybake::python

PYBIND11_MODULE(_skybake, m) {
  m.doc() = "skybake: precomputed atmospheric scattering (the compiled part; use the skybake package)";
  static py::exception<skybake::Error> bad_input(m, "BadInput", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const skybake::Error& e) {
      if (e.kind() == skybake::ErrorKind::BadInput) {
        bad_input(e.what());
      } else {
        PyErr_SetString(PyExc_RuntimeError, e.what());
      }
    }
  });
  skybake::python::registerLookups(m);
  skybake::python::registerBake(m);
  skybake::python::registerValidate(m);
  skybake::python::registerScene(m);
  m.attr("__version__") = SKYBAKE_VERSION;
}
