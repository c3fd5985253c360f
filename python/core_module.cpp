// magfem._core: the compiled part of the Python package (issue 32). It binds library calls,
// never the command line; python/magfem/__init__.py wraps it into the public classes.
#include <map>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "casefile/case_spec.hpp"
#include "core/input_error.hpp"
#include "python/actuator.hpp"
#include "python/analytic.hpp"
#include "python/call_checkpoint.hpp"
#include "python/coil_pitch.hpp"
#include "python/optimize.hpp"
#include "python/solution.hpp"
#include "python/study.hpp"
#include "python/sweep.hpp"
#include "python/validate.hpp"

namespace py = pybind11;

namespace {

py::list resolved_parameters(const magfem::CaseSpec& spec);

// Reads and validates a case: `text` is the YAML (from a file or a dumped dict), `name` stands
// for the file in messages. Returns the resolved parameters as [(name, value), ...] in file
// order; an invalid case raises _InputError carrying file, line and field.
py::list check_case_text(const std::string& text, const std::string& name,
                         const std::map<std::string, double>& overrides) {
  return resolved_parameters(magfem::read_case_text(text, name, overrides));
}

py::list resolved_parameters(const magfem::CaseSpec& spec) {
  py::list params;
  for (const auto& p : spec.parameters)
    params.append(py::make_tuple(p.name, p.value));
  return params;
}

// The same for a case file (relative paths in it resolve against its folder).
py::list check_case_file(const std::string& path, const std::map<std::string, double>& overrides) {
  return resolved_parameters(magfem::read_case(path, overrides));
}

} // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "Compiled part of the magfem package; use `import magfem`.";
  m.attr("__version__") = MAGFEM_VERSION;
  static py::exception<magfem::InputError> input_error(m, "_InputError", PyExc_ValueError);
  static py::exception<magfem::SolveError> solve_error(m, "_SolveError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p)
        std::rethrow_exception(p);
    } catch (const magfem::InputError& e) {
      py::object err = py::reinterpret_borrow<py::object>(input_error.ptr())(py::str(e.what()));
      err.attr("file") = e.file();
      err.attr("line") = e.line() > 0 ? py::object(py::int_(e.line())) : py::object(py::none());
      err.attr("field") =
          e.field().empty() ? py::object(py::none()) : py::object(py::str(e.field()));
      PyErr_SetObject(input_error.ptr(), err.ptr());
    } catch (const magfem::SolveError& e) {
      solve_error(e.what());
    }
  });
  m.def("check_case_text", &check_case_text, py::arg("text"), py::arg("name"),
        py::arg("overrides") = std::map<std::string, double>{},
        "Reads and validates a case from its YAML text; returns [(parameter, value), ...].");
  m.def("check_case_file", &check_case_file, py::arg("path"),
        py::arg("overrides") = std::map<std::string, double>{},
        "Reads and validates a case file; returns [(parameter, value), ...].");
  magfem::python::bind_solution(m);
  magfem::python::bind_analytic(m);
  magfem::python::bind_checkpoint_request(m);
  magfem::python::bind_sweep(m);
  magfem::python::bind_study(m);
  magfem::python::bind_actuator(m);
  magfem::python::bind_coil_pitch(m);
  magfem::python::bind_validate(m);
  magfem::python::bind_optimize(m);
}
