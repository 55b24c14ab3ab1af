// What the Python module's source files share: the pieces each registers
// with the module (python_module.cpp makes the module and calls them).
#pragma once

#include <pybind11/pybind11.h>

namespace skybake::python {

// skybake._skybake.Sky: the lookups over rows of float64 vectors.
void registerLookups(pybind11::module_& m);
// skybake._skybake.bake: a config (TOML path or dict) into a bake file.
void registerBake(pybind11::module_& m);
// skybake._skybake.validate: a bake against the reference, as a dict.
void registerValidate(pybind11::module_& m);
// The local frame's angles as vectors, and Sky.render's images.
void registerScene(pybind11::module_& m);

// A threads= argument as a thread count, checked as the command line's
// --threads (requireThreadCount): a Python int of any size, or BadInput.
int threadCountArgument(const pybind11::handle& threads);

}  // namespace skybake::python
