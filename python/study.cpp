#include "python/study.hpp"

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "core/input_error.hpp"
#include "python/background_call.hpp"
#include "python/call_checkpoint.hpp"
#include "python/case_source.hpp"
#include "python/option_arguments.hpp"
#include "studies/study.hpp"

namespace py = pybind11;

namespace magfem::python {
namespace {

const std::string where = "<study>";

struct StudyRequest {
  std::vector<std::pair<std::string, std::vector<double>>> parameters; // grid, in order
  std::vector<std::string> objectives;                                 // peak_torque, torque_at:DEG
  std::string rotate, axis;
  std::vector<double> angles; // degrees
  bool analytic = true;
  int jobs = 0, order = 0;
  double mesh_scale = 0;
  // FE: the adaptive solve of every position (--accuracy, --max-passes, --max-unknowns).
  std::optional<double> accuracy;
  std::optional<int> max_passes;
  std::optional<double> max_unknowns;
  CheckpointRequest checkpoint;
};

StudyOptions study_options(const std::string& file, const StudyRequest& q) {
  StudyOptions o;
  o.case_file = file;
  if (q.parameters.empty())
    throw InputError(where, 0, "params", "give at least one parameter and its values");
  for (const auto& [name, values] : q.parameters) {
    if (values.empty())
      throw InputError(where, 0, "params", "no values for '" + name + "'");
    o.parameters.push_back({name, values});
  }
  if (q.objectives.empty())
    throw InputError(where, 0, "objectives", "give at least one objective");
  for (const auto& text : q.objectives)
    o.objectives.push_back(parse_study_objective(text));
  if (q.rotate.empty())
    throw InputError(where, 0, "rotate", "name the group whose torque the objectives take");
  if (q.axis.empty())
    throw InputError(where, 0, "axis", "give the rotation axis");
  o.sweep.group = q.rotate;
  o.sweep.axis = parse_axis(q.axis);
  o.sweep.angles_deg = q.angles;
  for (const auto& obj : o.objectives)
    if (obj.kind == StudyObjective::Kind::peak_torque && q.angles.empty())
      throw InputError(where, 0, "angles", "peak_torque needs the angles of its sweep");
  if (q.jobs < 0)
    throw InputError(where, 0, "jobs", "must be a positive integer");
  if (q.order != 0 && q.order != 1 && q.order != 2)
    throw InputError(where, 0, "order", "must be 1 or 2");
  if (!(q.mesh_scale > 0))
    throw InputError(where, 0, "mesh_scale", "must be a positive number");
  o.adapt = adapt_arguments(where, q.accuracy, q.max_passes, q.max_unknowns);
  // As the command line refuses them without --fe: an ignored accuracy would look as if met.
  for (const auto& [given, name] : {std::pair{q.accuracy.has_value(), "accuracy"},
                                    std::pair{q.max_passes.has_value(), "max_passes"},
                                    std::pair{q.max_unknowns.has_value(), "max_unknowns"}})
    if (given && q.analytic)
      throw InputError(where, 0, name,
                       "refines the FE mesh: give analytic=False (the analytic models have no "
                       "mesh)");
  o.sweep.analytic = q.analytic;
  o.sweep.jobs = q.jobs;
  o.sweep.order = q.order;
  o.sweep.mesh_scale = q.mesh_scale;
  o.quiet = true; // progress goes through the callable
  return o;
}

// study.csv's columns over the successful designs: the parameters, the objectives, then
// (FE) each objective's estimated error `<objective>_err` (N m; NaN where none, an empty
// cell in study.csv).
py::dict study_columns(const StudyOptions& o, const std::vector<StudyDesign>& designs) {
  std::vector<const StudyDesign*> ok;
  for (const auto& d : designs)
    if (d.ok)
      ok.push_back(&d);
  py::dict out;
  auto column = [&](const std::string& name, auto value) {
    py::array_t<double> col(static_cast<py::ssize_t>(ok.size()));
    auto a = col.mutable_unchecked<1>();
    for (std::size_t i = 0; i < ok.size(); ++i)
      a(i) = value(*ok[i]);
    out[py::str(name)] = col;
  };
  for (std::size_t k = 0; k < o.parameters.size(); ++k)
    column(o.parameters[k].name, [k](const StudyDesign& d) { return d.parameters[k]; });
  for (std::size_t k = 0; k < o.objectives.size(); ++k)
    column(o.objectives[k].name, [k](const StudyDesign& d) { return d.objectives[k]; });
  if (!o.sweep.analytic)
    for (std::size_t k = 0; k < o.objectives.size(); ++k)
      column(o.objectives[k].name + "_err",
             [k](const StudyDesign& d) { return d.objective_errors[k]; });
  return out;
}

py::dict study_case(const std::string& path, const std::string& text, const std::string& name,
                    const std::map<std::string, double>& parameters, const StudyRequest& request,
                    py::object progress) {
  StudyOptions o = study_options(path.empty() ? name : path, request);
  // The case's own parameter overrides, under each design's values.
  o.read = [&](const ParameterOverrides& design) {
    std::map<std::string, double> merged = parameters;
    for (const auto& [k, v] : design)
      merged[k] = v;
    return read_python_case(path, text, name, merged);
  };
  BackgroundCall call(std::move(progress), "design");
  o.sweep.stop = call.stop_token();
  const auto checkpoint = open_call_checkpoint(
      request.checkpoint, where,
      case_call_identity("study", study_checkpoint_options(o), path, text, parameters));
  std::vector<StudyDesign> designs;
  try {
    call.run([&] {
      designs =
          run_study(o, checkpoint.get(), [&](int done, int total) { call.report(done, total); });
    });
  } catch (const InputError& e) { // the case's adapt: against the limits given, say
    throw as_argument_error(e, where, adapt_argument_names());
  }
  if (checkpoint)
    checkpoint->remove(); // the result is complete
  py::dict out;
  out["columns"] = study_columns(o, designs);
  out["summary"] = study_summary(o, designs).dump();
  return out;
}

} // namespace

void bind_study(py::module_& m) {
  py::class_<StudyRequest>(m, "StudyRequest", "The arguments of magfem.study.")
      .def(py::init<>())
      .def_readwrite("parameters", &StudyRequest::parameters)
      .def_readwrite("objectives", &StudyRequest::objectives)
      .def_readwrite("rotate", &StudyRequest::rotate)
      .def_readwrite("axis", &StudyRequest::axis)
      .def_readwrite("angles", &StudyRequest::angles)
      .def_readwrite("analytic", &StudyRequest::analytic)
      .def_readwrite("jobs", &StudyRequest::jobs)
      .def_readwrite("order", &StudyRequest::order)
      .def_readwrite("mesh_scale", &StudyRequest::mesh_scale)
      .def_readwrite("accuracy", &StudyRequest::accuracy)
      .def_readwrite("max_passes", &StudyRequest::max_passes)
      .def_readwrite("max_unknowns", &StudyRequest::max_unknowns)
      .def_readwrite("checkpoint", &StudyRequest::checkpoint);
  m.def("study", &study_case, py::arg("path"), py::arg("text"), py::arg("name"),
        py::arg("parameters"), py::arg("request"), py::arg("progress"),
        "Runs `magfem study` in-process; returns {'columns': {name: array}, 'summary': json}.");
}

} // namespace magfem::python
