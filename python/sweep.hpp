#pragma once
// magfem._core.sweep: `magfem sweep` in-process (studies/sweep.hpp, sweep_planar.hpp,
// sweep_axi.hpp), its sweep.csv as numpy columns and its summary.json as JSON text.
// python/magfem/studies.py wraps it into magfem.sweep.
#include <pybind11/pybind11.h>

namespace magfem::python {

void bind_sweep(pybind11::module_& m);

} // namespace magfem::python
