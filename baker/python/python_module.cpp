// The compiled part of `import skybake` (skybake._skybake). skybake::Error of
// kind BadInput becomes skybake.BadInput, a ValueError carrying the message
// the command line prints; other kinds become RuntimeError.
#include <pybind11/pybind11.h>

#include "baker/python/python_bindings.h"
#include "data_formats/error.h"

namespace py = pybind11;

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
}
