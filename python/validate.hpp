#pragma once
// magfem._core.validate: `magfem validate` in-process (validation/validate.hpp): the selected
// catalogue entries evaluated, results.json's content returned as JSON text, nothing written.
// python/magfem/studies.py wraps it.
#include <pybind11/pybind11.h>

namespace magfem::python {

void bind_validate(pybind11::module_& m);

} // namespace magfem::python
