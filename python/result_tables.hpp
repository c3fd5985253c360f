#pragma once
// What the Python solutions (solution.hpp, analytic.hpp) share: probe tables as numpy
// columns.
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "postproc/probe_table.hpp"

namespace magfem::python {

// name -> {column: 1-D numpy array}, the CSV files' columns in full precision.
pybind11::dict probes_dict(const std::vector<ProbeTable>& probes);

} // namespace magfem::python
