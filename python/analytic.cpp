#include "python/analytic.hpp"

#include <map>

#include <pybind11/stl.h>

#include "python/case_source.hpp"
#include "python/result_tables.hpp"

namespace py = pybind11;

namespace magfem::python {
namespace {

std::unique_ptr<Analytic> analytic_case(const std::string& path, const std::string& text,
                                        const std::string& name,
                                        const std::map<std::string, double>& parameters,
                                        const std::string& model, double tolerance, int n_max) {
  CaseSpec spec = read_python_case(path, text, name, parameters);
  AnalyticOptions options;
  options.model = model;
  options.tolerance = tolerance;
  options.n_max = n_max;
  const py::gil_scoped_release release; // milliseconds to seconds: quadrature per point
  return std::make_unique<Analytic>(run_case_analytic(std::move(spec), options));
}

} // namespace

std::string Analytic::forces_json() const {
  return magfem::forces_json(run_->forces).dump();
}

py::dict Analytic::probes() const {
  return probes_dict(run_->probes);
}

std::vector<std::string> Analytic::write(const std::string& dir) const {
  const py::gil_scoped_release release;
  const std::lock_guard lock(output_mutex_);
  return write_outputs_analytic(*run_, dir);
}

std::string Analytic::summary_json() const {
  return summary_json_analytic(*run_).dump();
}

void bind_analytic(py::module_& m) {
  py::class_<Analytic>(m, "Analytic", "An analytic answer (use magfem.analytic).")
      .def("forces_json", &Analytic::forces_json)
      .def("probes", &Analytic::probes)
      .def("write", &Analytic::write, py::arg("dir"))
      .def("summary_json", &Analytic::summary_json);
  m.def("analytic", &analytic_case, py::arg("path"), py::arg("text"), py::arg("name"),
        py::arg("parameters"), py::arg("model"), py::arg("tolerance"), py::arg("n_max"),
        "Reads a case and answers it with the analytic models (magfem analytic).");
}

} // namespace magfem::python
