#pragma once
// magfem._core.Solution: a solved case (the Run2D or Run3D of pipeline/run2d.hpp,
// pipeline/run3d.hpp, mesh and field kept alive) with what Python reads from it.
// python/magfem/solution.py wraps it into the public magfem.Solution (units, dicts, docstrings).
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "pipeline/run2d.hpp"
#include "pipeline/run3d.hpp"
#include "postproc/point_locator2d.hpp"
#include "postproc/point_locator3d.hpp"

namespace magfem::python {

class Solution {
public:
  explicit Solution(std::unique_ptr<Run2D> run);
  explicit Solution(std::unique_ptr<Run3D> run);

  std::string dimension() const; // "2d", "axi" or "3d"
  // The total energy as summary.json's energy_J (2D: per metre, or per stack length).
  double energy_J() const;
  // forces_json / coil results as JSON text: the same functions that write summary.json, so
  // fields added there (error estimates) reach Python without a change here.
  std::string forces_json() const;
  std::string coils_json() const;
  pybind11::object inductance_H() const; // 3D coils: numpy matrix; else None
  pybind11::dict probes() const;         // name -> {column: numpy array}
  // B (T) or H (A/m) at N x 3 points in metres, N x 3 Cartesian out; NaN rows outside the
  // meshed physical domain. Planar: z ignored. Axisymmetric: r = hypot(x, y) about the z axis.
  // 3D B and H are the patch-recovered fields (PatchRecovery3D), as the probe CSVs.
  pybind11::array_t<double> field_at(const pybind11::array_t<double>& points_m, bool want_H);
  pybind11::dict mesh() const;
  // The command line's outputs (write_outputs_2d/3d) into `dir`; returns the files written.
  std::vector<std::string> write(const std::string& dir) const;
  // summary.json as the command line writes it (the writer's own summary_json_2d/3d).
  std::string summary_json() const;
  // The warning of an adaptive solve that stopped at a limit before its accuracy (the text
  // the command line prints, adapt_loop.hpp adapt_warning); "" otherwise.
  std::string adapt_warning() const;

private:
  Eigen::Vector3d field_2d(const Eigen::Vector3d& x, bool want_H) const;
  Eigen::Vector3d field_3d(const Eigen::Vector3d& x, bool want_H) const;

  std::unique_ptr<Run2D> run2d_;
  std::unique_ptr<Run3D> run3d_;
  // Built at the first field_at (with the GIL held, so never twice); they refer to the mesh
  // of the run above, which never moves.
  std::unique_ptr<PointLocator2D> locator2d_;
  std::unique_ptr<PointLocator3D> locator3d_;
  // write() runs without the GIL: one at a time.
  mutable std::mutex output_mutex_;
};

// Registers Solution and solve() on the module.
void bind_solution(pybind11::module_& m);

} // namespace magfem::python
