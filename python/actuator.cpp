#include "python/actuator.hpp"

#include <array>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "core/input_error.hpp"
#include "python/case_source.hpp"
#include "python/py_progress.hpp"
#include "studies/actuator.hpp"

namespace py = pybind11;

namespace magfem::python {
namespace {

struct ActuatorRequest {
  std::string rotor;
  // Either the command line's --orientations text or rows of (rx, ry, rz) in degrees.
  std::string orientations_text;
  std::vector<std::array<double, 3>> orientations;
  std::optional<std::array<double, 3>> torque_Nm; // none: the unit torques about x, y, z
  bool analytic = true;
  int order = 0;
  double mesh_scale = 0;
};

py::array_t<double> matrix(py::ssize_t rows, py::ssize_t cols,
                           const std::function<double(py::ssize_t, py::ssize_t)>& at) {
  py::array_t<double> out({rows, cols});
  auto a = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < rows; ++i)
    for (py::ssize_t k = 0; k < cols; ++k)
      a(i, k) = at(i, k);
  return out;
}

// One demand's commutations over the orientations, as commutation.csv's columns: currents
// (orientations x coils, A), P_W, i_peak_A, cond_Gamma, and ok (ill-conditioned rows: NaN
// where the CSV leaves the cell empty).
py::dict demand_dict(const ActuatorDemand& d, std::size_t n_coils) {
  const auto n = static_cast<py::ssize_t>(d.commutations.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto& c = d.commutations;
  py::dict out;
  out["torque_Nm"] = matrix(1, 3, [&](auto, auto k) { return d.torque_Nm[k]; }).reshape({3});
  out["currents_A"] = matrix(n, static_cast<py::ssize_t>(n_coils),
                             [&](auto i, auto k) { return c[i].ok ? c[i].currents(k) : nan; });
  out["P_W"] =
      matrix(n, 1, [&](auto i, auto) { return c[i].ok ? c[i].power_W : nan; }).reshape({n});
  out["i_peak_A"] =
      matrix(n, 1, [&](auto i, auto) { return c[i].ok ? c[i].peak_A : nan; }).reshape({n});
  out["cond_Gamma"] = matrix(n, 1, [&](auto i, auto) { return c[i].condition; }).reshape({n});
  std::vector<bool> ok;
  for (const auto& x : c)
    ok.push_back(x.ok);
  out["ok"] = py::array(py::cast(ok));
  return out;
}

py::dict actuator_case(const std::string& path, const std::string& text, const std::string& name,
                       const std::map<std::string, double>& parameters,
                       const ActuatorRequest& request, py::object progress) {
  if (request.order != 0 && request.order != 1 && request.order != 2)
    throw InputError("<actuator>", 0, "order", "must be 1 or 2");
  if (!(request.mesh_scale > 0))
    throw InputError("<actuator>", 0, "mesh_scale", "must be a positive number");
  std::vector<Orientation> orientations;
  if (!request.orientations_text.empty())
    orientations = parse_orientations(request.orientations_text);
  for (const auto& o : request.orientations)
    orientations.push_back({o[0], o[1], o[2]});
  if (orientations.empty())
    throw InputError("<actuator>", 0, "orientations", "give at least one orientation");
  const CaseSpec spec = read_python_case(path, text, name, parameters);
  check_actuator_case(spec, request.rotor);
  ActuatorOptions options;
  options.rotor = request.rotor;
  options.analytic = request.analytic;
  options.order = request.order;
  options.mesh_scale = request.mesh_scale;
  if (request.torque_Nm)
    options.torque_Nm =
        Eigen::Vector3d((*request.torque_Nm)[0], (*request.torque_Nm)[1], (*request.torque_Nm)[2]);
  // FE solves report their stages (and look for Ctrl-C there) as case.solve's do; they run
  // one after another on this thread.
  PyProgress reporter(std::move(progress));
  options.progress = &reporter;
  ActuatorResult r;
  {
    const py::gil_scoped_release release;
    r = run_actuator(spec, options, orientations);
    reporter.rethrow_pending();
  }
  const auto n = static_cast<py::ssize_t>(r.orientations.size());
  const auto n_coils = static_cast<py::ssize_t>(r.coil_names.size());
  py::dict out;
  out["method"] = r.method;
  out["coils"] = r.coil_names;
  out["resistance_ohm"] =
      matrix(n_coils, 1, [&](auto k, auto) { return r.resistance_ohm(k); }).reshape({n_coils});
  out["orientations_deg"] = matrix(n, 3, [&](auto i, auto k) {
    const Orientation& o = r.orientations[i];
    return k == 0 ? o.rx_deg : k == 1 ? o.ry_deg : o.rz_deg;
  });
  // Gamma per orientation: 3 x coils (N m/A), the torque_constants.csv rows.
  py::array_t<double> gamma({n, py::ssize_t{3}, n_coils});
  auto g = gamma.mutable_unchecked<3>();
  for (py::ssize_t i = 0; i < n; ++i)
    for (py::ssize_t a = 0; a < 3; ++a)
      for (py::ssize_t k = 0; k < n_coils; ++k)
        g(i, a, k) = r.gamma[i](a, k);
  out["gamma"] = gamma;
  py::dict demands;
  for (const auto& d : r.demands)
    demands[py::str(d.name)] = demand_dict(d, r.coil_names.size());
  out["commutations"] = demands;
  out["n_field_solves"] = r.n_field_solves;
  out["notes"] = r.notes;
  return out;
}

} // namespace

void bind_actuator(py::module_& m) {
  py::class_<ActuatorRequest>(m, "ActuatorRequest", "The arguments of magfem.actuator.")
      .def(py::init<>())
      .def_readwrite("rotor", &ActuatorRequest::rotor)
      .def_readwrite("orientations_text", &ActuatorRequest::orientations_text)
      .def_readwrite("orientations", &ActuatorRequest::orientations)
      .def_readwrite("torque_Nm", &ActuatorRequest::torque_Nm)
      .def_readwrite("analytic", &ActuatorRequest::analytic)
      .def_readwrite("order", &ActuatorRequest::order)
      .def_readwrite("mesh_scale", &ActuatorRequest::mesh_scale);
  m.def("actuator", &actuator_case, py::arg("path"), py::arg("text"), py::arg("name"),
        py::arg("parameters"), py::arg("request"), py::arg("progress"),
        "Runs `magfem actuator` in-process; returns its tables as numpy arrays.");
}

} // namespace magfem::python
