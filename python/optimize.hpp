#pragma once
// magfem._core.optimize: `magfem optimize` in-process (studies/optimize.hpp), its result kept
// so that Python reads the history as numpy columns and the summary, and writes the command
// line's outputs. python/magfem/optimize.py wraps it into magfem.optimize.
#include <pybind11/pybind11.h>

namespace magfem::python {

void bind_optimize(pybind11::module_& m);

} // namespace magfem::python
