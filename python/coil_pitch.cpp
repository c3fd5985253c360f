#include "python/coil_pitch.hpp"

#include <array>
#include <map>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "core/input_error.hpp"
#include "python/case_source.hpp"
#include "python/option_arguments.hpp"
#include "studies/actuator_coil_pitch.hpp"

namespace py = pybind11;

namespace magfem::python {
namespace {

const std::string where = "<coil_pitch>";

// The arguments of magfem.coil_pitch: the pitches and the orientations as the command
// line's text, or the orientations as rows of (rx, ry, rz) in degrees.
struct CoilPitchRequest {
  std::string rotor;
  std::string pitches; // --coil-pitch START:STEP:END or a comma list (degrees)
  std::string orientations_text;
  std::vector<std::array<double, 3>> orientations;
  std::string coil_quadrature; // --coil-quadrature's text; empty: the default rule
};

// A coil-pitch study: its options (for the summary) and result.
class CoilPitchRun {
public:
  CoilPitchRun(ActuatorOptions options, CoilPitchStudy study)
      : options_(std::move(options)), study_(std::move(study)) {}

  // coil_pitch.csv's columns in full precision (counts as integers).
  py::dict columns() const {
    const auto n = static_cast<py::ssize_t>(study_.rows.size());
    py::dict out;
    const auto column = [&](const char* name, auto value) {
      using T = decltype(value(study_.rows.front()));
      py::array_t<T> col(n);
      for (py::ssize_t i = 0; i < n; ++i)
        col.mutable_at(i) = value(study_.rows[static_cast<std::size_t>(i)]);
      out[name] = col;
    };
    column("coil_pitch_deg", [](const CoilPitchRow& r) { return r.pitch_deg; });
    column("n_coils", [](const CoilPitchRow& r) { return r.n_coils; });
    column("G_w_deg", [](const CoilPitchRow& r) { return r.gap_deg; });
    column("C_w_deg", [](const CoilPitchRow& r) { return r.width_deg; });
    column("P_x_W", [](const CoilPitchRow& r) { return r.P_W[0]; });
    column("P_y_W", [](const CoilPitchRow& r) { return r.P_W[1]; });
    column("P_z_W", [](const CoilPitchRow& r) { return r.P_W[2]; });
    column("P_mean_W", [](const CoilPitchRow& r) { return r.mean_W(); });
    column("n_ill_x", [](const CoilPitchRow& r) { return r.n_ill[0]; });
    column("n_ill_y", [](const CoilPitchRow& r) { return r.n_ill[1]; });
    column("n_ill_z", [](const CoilPitchRow& r) { return r.n_ill[2]; });
    return out;
  }
  std::string csv() const { return coil_pitch_csv(study_); }
  std::string summary_json() const { return coil_pitch_summary(options_, study_).dump(); }

private:
  ActuatorOptions options_;
  CoilPitchStudy study_;
};

CoilPitchRun coil_pitch_case(const std::string& path, const std::string& text,
                             const std::string& name,
                             const std::map<std::string, double>& parameters,
                             const CoilPitchRequest& request) {
  ActuatorOptions o;
  o.case_file = path.empty() ? name : path;
  o.rotor = request.rotor;
  o.analytic = true; // the study's only model
  o.coil_pitch = request.pitches;
  o.orientations = request.orientations_text;
  o.parameters = parameters;
  std::vector<double> pitches;
  std::vector<Orientation> orientations;
  // The command's own checks and parsers, their messages with the arguments' names.
  try {
    pitches = coil_pitch_degrees(o);
    if (!request.coil_quadrature.empty())
      o.coil_rule = parse_coil_rule("--coil-quadrature", request.coil_quadrature);
    if (!request.orientations_text.empty())
      orientations = parse_orientations(request.orientations_text);
  } catch (const InputError& e) {
    throw as_argument_error(e, where,
                            {{"--coil-pitch", "pitches"},
                             {"--coil-quadrature", "coil_quadrature"},
                             {"--orientations", "orientations"}});
  }
  for (const auto& r : request.orientations)
    orientations.push_back({r[0], r[1], r[2]});
  if (orientations.empty())
    throw InputError(where, 0, "orientations", "give at least one orientation");
  const CaseSpec spec = read_python_case(path, text, name, parameters);
  check_actuator_case(spec, request.rotor);
  CoilPitchStudy study;
  try {
    const py::gil_scoped_release release;
    study = run_coil_pitch_study(spec, o, pitches, orientations);
  } catch (const InputError& e) { // a pitch outside the study's range names --coil-pitch
    throw as_argument_error(e, where, {{"--coil-pitch", "pitches"}});
  }
  return CoilPitchRun(std::move(o), std::move(study));
}

} // namespace

void bind_coil_pitch(py::module_& m) {
  py::class_<CoilPitchRequest>(m, "CoilPitchRequest", "The arguments of magfem.coil_pitch.")
      .def(py::init<>())
      .def_readwrite("rotor", &CoilPitchRequest::rotor)
      .def_readwrite("pitches", &CoilPitchRequest::pitches)
      .def_readwrite("orientations_text", &CoilPitchRequest::orientations_text)
      .def_readwrite("orientations", &CoilPitchRequest::orientations)
      .def_readwrite("coil_quadrature", &CoilPitchRequest::coil_quadrature);
  py::class_<CoilPitchRun>(m, "CoilPitchRun", "A coil-pitch study (use magfem.coil_pitch).")
      .def("columns", &CoilPitchRun::columns)
      .def("csv", &CoilPitchRun::csv)
      .def("summary_json", &CoilPitchRun::summary_json);
  m.def("coil_pitch", &coil_pitch_case, py::arg("path"), py::arg("text"), py::arg("name"),
        py::arg("parameters"), py::arg("request"),
        "Runs `magfem actuator --analytic --coil-pitch` in-process; returns a CoilPitchRun.");
}

} // namespace magfem::python
