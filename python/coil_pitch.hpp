#pragma once
// magfem._core.coil_pitch: `magfem actuator --analytic --coil-pitch` in-process
// (studies/actuator_coil_pitch.hpp): the mean copper loss against the coil pitch as numpy
// columns. python/magfem/studies.py wraps it (magfem.coil_pitch).
#include <pybind11/pybind11.h>

namespace magfem::python {

void bind_coil_pitch(pybind11::module_& m);

} // namespace magfem::python
