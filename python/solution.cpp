#include "python/solution.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include <nlohmann/json.hpp>
#include <pybind11/stl.h>

#include "core/input_error.hpp"
#include "pipeline/solve_case.hpp"
#include "python/case_source.hpp"
#include "python/option_arguments.hpp"
#include "python/py_progress.hpp"
#include "python/result_tables.hpp"

namespace py = pybind11;

namespace magfem::python {
namespace {

template <typename Vec> py::array_t<double> rows_of(const std::vector<Vec>& v, int dim) {
  py::array_t<double> out({static_cast<py::ssize_t>(v.size()), static_cast<py::ssize_t>(dim)});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int k = 0; k < dim; ++k)
      a(i, k) = v[i][k];
  return out;
}

template <std::size_t N> py::array_t<int> rows_of(const std::vector<std::array<int, N>>& v) {
  py::array_t<int> out({static_cast<py::ssize_t>(v.size()), static_cast<py::ssize_t>(N)});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t k = 0; k < N; ++k)
      a(i, k) = v[i][k];
  return out;
}

std::unique_ptr<Solution>
solve_case(const std::string& path, const std::string& text, const std::string& name,
           const std::map<std::string, double>& parameters, int order, double mesh_scale,
           py::object progress, std::optional<double> accuracy_pct, std::optional<int> max_passes,
           std::optional<double> max_unknowns) {
  // Checked as the command line checks --order and --mesh-scale (0 would mean "as in the
  // case" to RunOverrides, so it is refused rather than passed on).
  if (order != 0 && order != 1 && order != 2)
    throw InputError("<solve>", 0, "order", "must be 1 or 2");
  if (!(mesh_scale > 0) || !std::isfinite(mesh_scale))
    throw InputError("<solve>", 0, "mesh_scale", "must be a positive number");
  // The command line's checks of --accuracy, --max-passes and --max-unknowns.
  const AdaptOverrides adapt = adapt_arguments("<solve>", accuracy_pct, max_passes, max_unknowns);
  CaseSpec spec = read_python_case(path, text, name, parameters);
  apply_adapt_overrides(spec.adapt, adapt, {"<solve>", "accuracy", "max_passes", "max_unknowns"});
  PyProgress reporter(std::move(progress));
  RunOverrides overrides;
  overrides.order = order;
  overrides.mesh_scale = mesh_scale;
  overrides.progress = &reporter;
  // Each pass of an adaptive solve as the command line prints it, as a "note" (which is also
  // where Ctrl-C between passes is seen).
  const char* element_word = spec.dimension == 3 ? "tetrahedra" : "triangles";
  const auto on_pass = [&reporter, element_word](const AdaptPass& p) {
    const std::string line = describe_adapt_pass(p, element_word);
    reporter.note(line.substr(0, line.find_last_not_of('\n') + 1));
  };
  std::unique_ptr<Solution> solution;
  {
    // Minutes on a large case: other Python threads run meanwhile, and PyProgress takes the
    // GIL back for a moment at each report to look for Ctrl-C.
    const py::gil_scoped_release release;
    if (spec.dimension == 3)
      solution = std::make_unique<Solution>(solve_case_3d(std::move(spec), overrides, on_pass));
    else
      solution = std::make_unique<Solution>(solve_case_2d(std::move(spec), overrides, on_pass));
    reporter.rethrow_pending();
  }
  return solution;
}

} // namespace

Solution::Solution(std::unique_ptr<Run2D> run) : run2d_(std::move(run)) {}
Solution::Solution(std::unique_ptr<Run3D> run) : run3d_(std::move(run)) {}

std::string Solution::dimension() const {
  if (run3d_)
    return "3d";
  return run2d_->spec.axisymmetric() ? "axi" : "2d";
}

double Solution::energy_J() const {
  if (run3d_)
    return run3d_->energy.total_J;
  const double length = run2d_->spec.stack_length > 0 ? run2d_->spec.stack_length : 1.0;
  return run2d_->energy.total_J_per_m * length;
}

std::string Solution::forces_json() const {
  return magfem::forces_json(run3d_ ? run3d_->forces : run2d_->forces).dump();
}

std::string Solution::coils_json() const {
  if (run3d_)
    return coil_results_json(run3d_->coil_results).dump();
  return coils_json_2d(run2d_->coil_results).dump();
}

py::object Solution::inductance_H() const {
  const Eigen::MatrixXd& l = run3d_ ? run3d_->coil_results.inductance_H : run2d_->inductance_H;
  if (l.size() == 0)
    return py::none();
  py::array_t<double> out({static_cast<py::ssize_t>(l.rows()), static_cast<py::ssize_t>(l.cols())});
  auto a = out.mutable_unchecked<2>();
  for (Eigen::Index i = 0; i < l.rows(); ++i)
    for (Eigen::Index k = 0; k < l.cols(); ++k)
      a(i, k) = l(i, k);
  return out;
}

py::dict Solution::probes() const {
  return probes_dict(run3d_ ? run3d_->probes : run2d_->probes);
}

Eigen::Vector3d Solution::field_2d(const Eigen::Vector3d& x, bool want_H) const {
  const bool axi = run2d_->spec.axisymmetric();
  // Axisymmetric: the r-z half plane the mesh lives in, then Br back along (x, y) / r.
  const double r = std::hypot(x.x(), x.y());
  const Eigen::Vector2d q = axi ? Eigen::Vector2d(r, x.z()) : Eigen::Vector2d(x.x(), x.y());
  const auto loc = locator2d_->locate(q);
  if (!loc)
    return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  const Field2D& field = *run2d_->field;
  // Beyond a symmetry plane: H from B at the mirror image, both mapped back the same way.
  const Eigen::Vector2d b = run2d_->recovery->B(loc->triangle, loc->bary); // as the probes
  const Eigen::Vector2d v =
      loc->b_map *
      (want_H ? field.H(loc->triangle, fold_point_2d(run2d_->mesh.symmetry, q).point, b) : b);
  if (!axi)
    return {v.x(), v.y(), 0.0};
  // On the axis the radial component vanishes by symmetry: any direction will do.
  const double cx = r > 0 ? x.x() / r : 1.0, cy = r > 0 ? x.y() / r : 0.0;
  return {v.x() * cx, v.x() * cy, v.y()};
}

Eigen::Vector3d Solution::field_3d(const Eigen::Vector3d& x, bool want_H) const {
  const auto loc = locator3d_->locate(x);
  if (!loc)
    return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  // B as the probes read it, and H with it: the patch recovery of the point's region
  // (probes3d.hpp).
  const PatchRecovery3D& recovery = *run3d_->recovery;
  return loc->b_map * (want_H ? recovery.H(loc->tet, loc->bary) : recovery.B(loc->tet, loc->bary));
}

py::array_t<double> Solution::field_at(const py::array_t<double>& points_m, bool want_H) {
  if (points_m.ndim() != 2 || points_m.shape(1) != 3)
    throw py::value_error("points must be an N x 3 array");
  if (run3d_ && !locator3d_)
    locator3d_ = std::make_unique<PointLocator3D>(run3d_->mesh);
  if (run2d_ && !locator2d_)
    locator2d_ = std::make_unique<PointLocator2D>(run2d_->mesh);
  const auto n = points_m.shape(0);
  py::array_t<double> out({n, static_cast<py::ssize_t>(3)});
  const auto in = points_m.unchecked<2>();
  auto a = out.mutable_unchecked<2>();
  {
    const py::gil_scoped_release release; // a plot's 10^5 points take a while
    for (py::ssize_t i = 0; i < n; ++i) {
      const Eigen::Vector3d x(in(i, 0), in(i, 1), in(i, 2));
      const Eigen::Vector3d v = run3d_ ? field_3d(x, want_H) : field_2d(x, want_H);
      for (int k = 0; k < 3; ++k)
        a(i, k) = v[k];
    }
  }
  return out;
}

py::dict Solution::mesh() const {
  py::dict out;
  py::list names;
  for (const auto& r : run3d_ ? run3d_->spec.regions : run2d_->spec.regions)
    names.append(r.name);
  out["region_names"] = names;
  if (run3d_) {
    out["nodes"] = rows_of(run3d_->mesh.nodes, 3);
    out["elements"] = rows_of(run3d_->mesh.tets);
    out["regions"] = py::array_t<int>(static_cast<py::ssize_t>(run3d_->mesh.tet_part.size()),
                                      run3d_->mesh.tet_part.data());
  } else {
    out["nodes"] = rows_of(run2d_->mesh.nodes, 2);
    out["elements"] = rows_of(run2d_->mesh.triangles);
    out["regions"] = py::array_t<int>(static_cast<py::ssize_t>(run2d_->mesh.triangle_part.size()),
                                      run2d_->mesh.triangle_part.data());
  }
  return out;
}

std::vector<std::string> Solution::write(const std::string& dir) const {
  const py::gil_scoped_release release; // the VTU of a 3D mesh takes seconds
  const std::lock_guard lock(output_mutex_);
  return run3d_ ? write_outputs_3d(*run3d_, dir) : write_outputs_2d(*run2d_, dir);
}

std::string Solution::adapt_warning() const {
  const auto& adapt = run3d_ ? run3d_->adapt : run2d_->adapt;
  return adapt ? magfem::adapt_warning(*adapt) : "";
}

std::string Solution::summary_json() const {
  return (run3d_ ? summary_json_3d(*run3d_) : summary_json_2d(*run2d_)).dump();
}

void bind_solution(py::module_& m) {
  py::class_<Solution>(m, "Solution", "A solved case (use magfem.Case.solve).")
      .def_property_readonly("dimension", &Solution::dimension)
      .def_property_readonly("energy_J", &Solution::energy_J)
      .def("forces_json", &Solution::forces_json)
      .def("coils_json", &Solution::coils_json)
      .def("inductance_H", &Solution::inductance_H)
      .def("probes", &Solution::probes)
      .def("field_at", &Solution::field_at, py::arg("points_m"), py::arg("want_H"))
      .def("mesh", &Solution::mesh)
      .def("write", &Solution::write, py::arg("dir"))
      .def("summary_json", &Solution::summary_json)
      .def("adapt_warning", &Solution::adapt_warning);
  m.def("solve", &solve_case, py::arg("path"), py::arg("text"), py::arg("name"),
        py::arg("parameters"), py::arg("order"), py::arg("mesh_scale"), py::arg("progress"),
        py::arg("accuracy_pct") = py::none(), py::arg("max_passes") = py::none(),
        py::arg("max_unknowns") = py::none(),
        "Reads a case (file `path`, else YAML `text` named `name`) and solves it in-process, "
        "adaptively when the case's adapt: section or `accuracy_pct` asks.");
}

} // namespace magfem::python
