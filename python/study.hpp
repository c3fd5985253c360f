#pragma once
// magfem._core.study: `magfem study` in-process (studies/study.hpp), its study.csv as numpy
// columns and its summary.json as JSON text. python/magfem/studies.py wraps it into
// magfem.study.
#include <pybind11/pybind11.h>

namespace magfem::python {

void bind_study(pybind11::module_& m);

} // namespace magfem::python
