#pragma once
// magfem._core.actuator: `magfem actuator` in-process (studies/actuator.hpp): the torque
// constants and the commutations as numpy arrays. python/magfem/studies.py wraps it.
#include <pybind11/pybind11.h>

namespace magfem::python {

void bind_actuator(pybind11::module_& m);

} // namespace magfem::python
