#include "python/optimize.hpp"

#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "core/input_error.hpp"
#include "python/background_call.hpp"
#include "python/case_source.hpp"
#include "python/option_arguments.hpp"
#include "studies/optimize.hpp"

namespace py = pybind11;

namespace magfem::python {
namespace {

const std::string where = "<optimize>";

// The arguments of magfem.optimize, as the command line's options take them (numbers in the
// parameters' own units, angles in degrees).
struct OptimizeRequest {
  std::vector<std::tuple<std::string, double, double>> vary; // name, lower, upper
  std::string objective;                                     // peak_torque, torque_at:DEG
  bool maximize = true;
  std::string rotate, axis;
  std::vector<double> angles;
  std::vector<std::string> constraints; // "EXPR <= EXPR"
  double xtol = 1e-4;
  bool verify_fe = false;
  int order = 0;
  double mesh_scale = 1.0;
};

// The command line's argument list for the request, so that parse_optimize_options checks
// and reads it exactly as `magfem optimize` does.
std::vector<std::string> optimize_args(const std::string& case_name, const OptimizeRequest& q) {
  std::vector<std::string> a{case_name,
                             q.maximize ? "--maximize" : "--minimize",
                             q.objective,
                             "--xtol",
                             option_number(q.xtol),
                             "--mesh-scale",
                             option_number(q.mesh_scale),
                             "--quiet"};
  for (const auto& [name, lower, upper] : q.vary)
    a.insert(a.end(), {"--vary", name + "=" + option_number(lower) + ":" + option_number(upper)});
  if (!q.rotate.empty())
    a.insert(a.end(), {"--rotate", q.rotate});
  if (!q.axis.empty())
    a.insert(a.end(), {"--axis", q.axis});
  if (!q.angles.empty()) {
    std::string list;
    for (double v : q.angles)
      list += (list.empty() ? "" : ",") + option_number(v);
    a.insert(a.end(), {"--angles", list});
  }
  for (const auto& c : q.constraints)
    a.insert(a.end(), {"--constraint", c});
  if (q.order != 0)
    a.insert(a.end(), {"--order", std::to_string(q.order)});
  if (q.verify_fe)
    a.push_back("--verify-fe");
  return a;
}

// The parser's errors with the arguments' Python names (the objective is study's
// --objective to the parser, and maximize or minimize here).
InputError optimize_argument_error(const InputError& e, bool maximize) {
  static const std::map<std::string, std::string> names = {{"--vary", "vary"},
                                                           {"--xtol", "xtol"},
                                                           {"--constraint", "constraints"},
                                                           {"--rotate", "rotate"},
                                                           {"--axis", "axis"},
                                                           {"--angles", "angles"},
                                                           {"--order", "order"},
                                                           {"--mesh-scale", "mesh_scale"}};
  const std::string sense = maximize ? "maximize" : "minimize";
  if (e.file() == "<command line>" &&
      (e.field() == "--objective" || e.field() == "--maximize" || e.field() == "--minimize"))
    return InputError(where, 0, sense, e.reason());
  return as_argument_error(e, where, names);
}

// An optimization run: its options (for the writers) and result.
class OptimizeRun {
public:
  OptimizeRun(OptimizeOptions options, OptimizeResult result)
      : options_(std::move(options)), result_(std::move(result)) {}

  std::string summary_json() const { return optimize_summary(options_, result_).dump(); }

  // history.csv's columns in full precision: evaluation, the variables, the objective.
  py::dict history() const {
    const auto n = static_cast<py::ssize_t>(result_.history.size());
    py::dict out;
    py::array_t<int> index(n);
    for (py::ssize_t k = 0; k < n; ++k)
      index.mutable_at(k) = static_cast<int>(k + 1);
    out["evaluation"] = index;
    auto column = [&](const std::string& name, auto value) {
      py::array_t<double> col(n);
      for (py::ssize_t k = 0; k < n; ++k)
        col.mutable_at(k) = value(result_.history[k]);
      out[py::str(name)] = col;
    };
    for (std::size_t i = 0; i < options_.variables.size(); ++i)
      column(options_.variables[i].name, [i](const OptimizeEvaluation& e) { return e.values[i]; });
    column(options_.study.objectives.front().name,
           [](const OptimizeEvaluation& e) { return e.objective; });
    return out;
  }

  std::string history_csv() const { return optimize_history_csv(options_, result_); }

  std::vector<std::string> write(const std::string& dir) const {
    return write_optimize_outputs(options_, result_, dir);
  }

private:
  OptimizeOptions options_;
  OptimizeResult result_;
};

OptimizeRun optimize_case(const std::string& path, const std::string& text, const std::string& name,
                          const std::map<std::string, double>& parameters,
                          const OptimizeRequest& request, py::object progress) {
  OptimizeOptions o;
  try {
    o = parse_optimize_options(optimize_args(path.empty() ? name : path, request));
  } catch (const InputError& e) {
    throw optimize_argument_error(e, request.maximize);
  }
  // The case's own parameter overrides, under each evaluation's values.
  o.study.read = [&](const ParameterOverrides& design) {
    std::map<std::string, double> merged = parameters;
    for (const auto& [k, v] : design)
      merged[k] = v;
    return read_python_case(path, text, name, merged);
  };
  BackgroundCall call(std::move(progress), "evaluation");
  o.study.sweep.stop = call.stop_token();
  OptimizeResult result;
  int done = 0;
  // The number of evaluations is not known ahead: the limit stands for the total.
  call.run([&] {
    result =
        run_optimize(o, [&](const OptimizeEvaluation&) { call.report(++done, o.max_evaluations); });
  });
  o.study.read = nullptr; // it refers to this call's arguments
  return OptimizeRun(std::move(o), std::move(result));
}

} // namespace

void bind_optimize(py::module_& m) {
  py::class_<OptimizeRequest>(m, "OptimizeRequest", "The arguments of magfem.optimize.")
      .def(py::init<>())
      .def_readwrite("vary", &OptimizeRequest::vary)
      .def_readwrite("objective", &OptimizeRequest::objective)
      .def_readwrite("maximize", &OptimizeRequest::maximize)
      .def_readwrite("rotate", &OptimizeRequest::rotate)
      .def_readwrite("axis", &OptimizeRequest::axis)
      .def_readwrite("angles", &OptimizeRequest::angles)
      .def_readwrite("constraints", &OptimizeRequest::constraints)
      .def_readwrite("xtol", &OptimizeRequest::xtol)
      .def_readwrite("verify_fe", &OptimizeRequest::verify_fe)
      .def_readwrite("order", &OptimizeRequest::order)
      .def_readwrite("mesh_scale", &OptimizeRequest::mesh_scale);
  py::class_<OptimizeRun>(m, "OptimizeRun", "An optimization run (use magfem.optimize).")
      .def("summary_json", &OptimizeRun::summary_json)
      .def("history", &OptimizeRun::history)
      .def("history_csv", &OptimizeRun::history_csv)
      .def("write", &OptimizeRun::write, py::arg("dir"));
  m.def("optimize", &optimize_case, py::arg("path"), py::arg("text"), py::arg("name"),
        py::arg("parameters"), py::arg("request"), py::arg("progress"),
        "Runs `magfem optimize` in-process; returns an OptimizeRun.");
}

} // namespace magfem::python
