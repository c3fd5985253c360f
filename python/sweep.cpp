#include "python/sweep.hpp"

#include <functional>
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
#include "studies/sweep.hpp"
#include "studies/sweep_axi.hpp"
#include "studies/sweep_planar.hpp"

namespace py = pybind11;

namespace magfem::python {
namespace {

const std::string where = "<sweep>";

// The columns of sweep.csv over the successful rows, in full precision: {name: 1-D array}.
template <class Row>
py::dict
csv_columns(const std::vector<Row>& rows,
            const std::vector<std::pair<const char*, std::function<double(const Row&)>>>& columns) {
  std::vector<const Row*> ok;
  for (const Row& r : rows)
    if (r.ok)
      ok.push_back(&r);
  py::dict out;
  for (const auto& [name, value] : columns) {
    py::array_t<double> col(static_cast<py::ssize_t>(ok.size()));
    auto a = col.mutable_unchecked<1>();
    for (std::size_t i = 0; i < ok.size(); ++i)
      a(i) = value(*ok[i]);
    out[name] = col;
  }
  return out;
}

// The columns of sweep_csv (studies/sweep.cpp), in its order; the position named as there.
py::dict rotation_columns(const std::vector<SweepRow>& rows, SweepMotion motion) {
  const std::string position = sweep_position_key(motion);
  return csv_columns<SweepRow>(rows,
                               {{position.c_str(), [](const SweepRow& r) { return r.angle_deg; }},
                                {"Tx", [](const SweepRow& r) { return r.torque.x(); }},
                                {"Ty", [](const SweepRow& r) { return r.torque.y(); }},
                                {"Tz", [](const SweepRow& r) { return r.torque.z(); }},
                                {"Fx", [](const SweepRow& r) { return r.force.x(); }},
                                {"Fy", [](const SweepRow& r) { return r.force.y(); }},
                                {"Fz", [](const SweepRow& r) { return r.force.z(); }}});
}

// The columns of sweep_axi_csv (studies/sweep_axi.cpp).
py::dict translation_columns(const std::vector<AxiSweepRow>& rows) {
  return csv_columns<AxiSweepRow>(
      rows, {{"position_mm", [](const AxiSweepRow& r) { return r.position_m * 1e3; }},
             {"Fz_N", [](const AxiSweepRow& r) { return r.fz_N; }}});
}

struct SweepRequest {
  std::string rotate, translate; // one of them: the group
  std::string axis;              // x|y|z or "ax,ay,az"; empty: z (planar, axi) or y (3D)
  std::vector<double> values;    // angles (deg) or positions (mm)
  bool analytic = false;
  std::optional<std::vector<double>> point; // case length unit
  std::optional<double> surface_radius;     // case length unit
  int jobs = 0, order = 0;
  double mesh_scale = 0;
  CheckpointRequest checkpoint;
};

// The case a sweep runs on, as the call names it (for the checkpoint's identity).
struct SweepCase {
  const CaseSpec& spec;
  const std::string &path, &text;
  const std::map<std::string, double>& parameters;
};

// The axial sweep, as `magfem sweep CASE_AXI --move GROUP --axis z --positions ...` runs it.
py::dict translate(const SweepCase& c, const SweepRequest& q, BackgroundCall& call) {
  const CaseSpec& spec = c.spec;
  if (!q.axis.empty() && q.axis != "z")
    throw InputError(where, 0, "axis", "an axisymmetric group moves along z: give axis=\"z\"");
  // Arguments of the rotating sweeps: refused rather than ignored.
  if (q.analytic)
    throw InputError(where, 0, "analytic", "translate sweeps are FE only");
  if (q.point || q.surface_radius)
    throw InputError(where, 0, q.point ? "point" : "surface_radius",
                     "not for translate sweeps (the group moves along the axis)");
  AxiSweepOptions o;
  o.group = q.translate;
  for (const double p : q.values)
    o.positions_m.push_back(1e-3 * p); // as the command line converts --positions
  o.jobs = q.jobs;
  o.order = q.order;
  o.mesh_scale = q.mesh_scale;
  o.stop = call.stop_token();
  const auto checkpoint =
      open_call_checkpoint(q.checkpoint, where,
                           case_call_identity("sweep --move", sweep_axi_checkpoint_options(o),
                                              c.path, c.text, c.parameters));
  o.checkpoint = checkpoint.get();
  std::vector<AxiSweepRow> rows;
  call.run([&] {
    rows = run_sweep_axi(spec, o, [&](int done, int total) { call.report(done, total); });
  });
  if (checkpoint)
    checkpoint->remove(); // the result is complete
  py::dict out;
  out["columns"] = translation_columns(rows);
  out["summary"] = sweep_axi_summary(spec, rows, o).dump();
  return out;
}

// The rotating sweep (3D or planar) and the 3D or planar translate sweep, as `magfem sweep
// --rotate GROUP ...` and `magfem sweep CASE --move GROUP ...` run them.
py::dict rotate_or_move_3d(const SweepCase& c, const SweepRequest& q, BackgroundCall& call) {
  const CaseSpec& spec = c.spec;
  const bool planar = spec.dimension == 2 && !spec.axisymmetric();
  const bool move = !q.translate.empty();
  SweepOptions o;
  o.group = move ? q.translate : q.rotate;
  if (move) {
    // As --move: the direction is asked for, never assumed; the group moves, nothing turns.
    if (q.axis.empty())
      throw InputError(where, 0, "axis", "give the direction to move along");
    // The torque's point, carried with the group (3D without it: about the origin).
    o.carry_point = q.point.has_value();
    o.motion = SweepMotion::translate;
    for (const double p : q.values)
      o.offsets_m.push_back(1e-3 * p); // as the command line converts --positions
  } else {
    o.angles_deg = q.values;
  }
  const std::string axis = q.axis.empty() ? (planar ? "z" : "y") : q.axis;
  o.axis = parse_axis(axis, planar);
  const double s = spec.length_unit;
  if (q.point) {
    if (q.point->size() != 3)
      throw InputError(where, 0, "point", "expected three numbers (x, y, z)");
    o.point = s * Eigen::Vector3d((*q.point)[0], (*q.point)[1], (*q.point)[2]);
  }
  if (q.surface_radius)
    o.surface_radius = s * *q.surface_radius;
  o.analytic = q.analytic;
  o.jobs = q.jobs;
  o.order = q.order;
  o.mesh_scale = q.mesh_scale;
  o.stop = call.stop_token();
  // The point and the surface radius as the command line's text would give them.
  std::string point, radius;
  for (std::size_t k = 0; q.point && k < q.point->size(); ++k)
    point.append(k ? "," : "").append(option_number((*q.point)[k]));
  if (q.surface_radius)
    radius = option_number(*q.surface_radius);
  const auto checkpoint =
      open_call_checkpoint(q.checkpoint, where,
                           case_call_identity(move ? "sweep --move" : "sweep --rotate",
                                              sweep_checkpoint_options(o, axis, point, radius),
                                              c.path, c.text, c.parameters));
  o.checkpoint = checkpoint.get();
  SweepJobs jobs;
  std::vector<SweepRow> rows;
  call.run([&] {
    const auto report = [&](int done, int total) { call.report(done, total); };
    rows = planar ? run_sweep_planar(spec, o, report, &jobs) : run_sweep(spec, o, report, &jobs);
  });
  if (checkpoint)
    checkpoint->remove(); // the result is complete
  py::dict out;
  out["columns"] = rotation_columns(rows, o.motion);
  out["summary"] = sweep_summary(spec.file, rows, o, jobs).dump();
  return out;
}

py::dict sweep_case(const std::string& path, const std::string& text, const std::string& name,
                    const std::map<std::string, double>& parameters, const SweepRequest& request,
                    py::object progress) {
  if (request.rotate.empty() == request.translate.empty())
    throw InputError(where, 0, request.rotate.empty() ? "rotate" : "translate",
                     "give one of rotate= (a group to turn) and translate= (a group to move)");
  if (request.values.empty())
    throw InputError(where, 0, request.rotate.empty() ? "positions" : "angles",
                     "give at least one position");
  if (request.jobs < 0)
    throw InputError(where, 0, "jobs", "must be a positive integer");
  if (request.order != 0 && request.order != 1 && request.order != 2)
    throw InputError(where, 0, "order", "must be 1 or 2");
  if (!(request.mesh_scale > 0))
    throw InputError(where, 0, "mesh_scale", "must be a positive number");
  const CaseSpec spec = read_python_case(path, text, name, parameters);
  BackgroundCall call(std::move(progress));
  const SweepCase c{spec, path, text, parameters};
  return request.translate.empty() || !spec.axisymmetric() ? rotate_or_move_3d(c, request, call)
                                                           : translate(c, request, call);
}

} // namespace

void bind_sweep(py::module_& m) {
  py::class_<SweepRequest>(m, "SweepRequest", "The arguments of magfem.sweep.")
      .def(py::init<>())
      .def_readwrite("rotate", &SweepRequest::rotate)
      .def_readwrite("translate", &SweepRequest::translate)
      .def_readwrite("axis", &SweepRequest::axis)
      .def_readwrite("values", &SweepRequest::values)
      .def_readwrite("analytic", &SweepRequest::analytic)
      .def_readwrite("point", &SweepRequest::point)
      .def_readwrite("surface_radius", &SweepRequest::surface_radius)
      .def_readwrite("jobs", &SweepRequest::jobs)
      .def_readwrite("order", &SweepRequest::order)
      .def_readwrite("mesh_scale", &SweepRequest::mesh_scale)
      .def_readwrite("checkpoint", &SweepRequest::checkpoint);
  m.def("sweep", &sweep_case, py::arg("path"), py::arg("text"), py::arg("name"),
        py::arg("parameters"), py::arg("request"), py::arg("progress"),
        "Runs `magfem sweep` in-process; returns {'columns': {name: array}, 'summary': json}.");
}

} // namespace magfem::python
