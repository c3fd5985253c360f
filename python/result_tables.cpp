#include "python/result_tables.hpp"

#include <pybind11/numpy.h>

namespace py = pybind11;

namespace magfem::python {

py::dict probes_dict(const std::vector<ProbeTable>& probes) {
  py::dict out;
  for (const ProbeTable& p : probes) {
    py::dict columns;
    for (std::size_t c = 0; c < p.columns.size(); ++c) {
      py::array_t<double> col(static_cast<py::ssize_t>(p.rows.size()));
      auto a = col.mutable_unchecked<1>();
      for (std::size_t r = 0; r < p.rows.size(); ++r)
        a(r) = p.rows[r][c];
      columns[py::str(p.columns[c])] = col;
    }
    out[py::str(p.name)] = columns;
  }
  return out;
}

} // namespace magfem::python
