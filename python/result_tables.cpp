#include "python/result_tables.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

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

TempDir::TempDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "magfem-py-XXXXXX").string();
  if (!mkdtemp(pattern.data()))
    throw std::runtime_error("cannot create a temporary folder like " + pattern);
  path_ = pattern;
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace magfem::python
