#pragma once
// One case end to end, planar, axisymmetric and 3D alike: the stage sequence of a solve written
// once (as deal.II's Step6<dim>::run() or MFEM tesla's Solve()), over a discretisation D that
// does each stage's dimension-specific work. run_case_2d and run_case_3d are this driver over
// Discretisation2D (run2d.cpp) and Discretisation3D (run3d.cpp).
//
// What D provides (d is constructed on the run record and the overrides):
//   types     Run (Run2D, Run3D), DofMap, Field, Locator, Assembler
//   static    apply_overrides(spec, ov); element_name ("triangles"); n_elements(mesh);
//             total_energy(run) (J, or J/m planar)
//   before    tune_linear_solver(options); check_before_mesh(); mesh(); check_mesh();
//             build_problem(); prepare_dofs() (3D: curved P2 nodes, coil source field);
//             make_assembler(); prepare_solver(assembler) (3D: p-multigrid levels)
//   solve     solve(assembler, u) -> NewtonReport; post_processes() (false on MPI ranks > 0)
//   after     recover() (3D: nodal B); summarize_energy(names); probe_locator() (3D: over the
//             probe points' box); sample_probe(locator, probe);
//             integrate_section(section); forces(); coil_results(assembler, u);
//             estimate_error() (seconds are timed here); check_finite_fields();
//             scale_to_whole_device() (symmetry planes); mesh_warnings()
// The stages report to the console (RunOverrides::progress) as "meshing", "assembly: N
// <elements>, order k" and "post-processing"; D may announce stages of its own in between.
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "casefile/case_spec.hpp"
#include "core/progress.hpp"
#include "pipeline/demagnetization_results.hpp"
#include "pipeline/result_checks.hpp"
#include "pipeline/run2d.hpp"
#include "pipeline/section_results.hpp"
#include "pipeline/timings.hpp"

namespace magfem {

// A stage on the console, when the run has one (null: silent, as in sweeps).
inline void announce_stage(Progress* progress, const std::string& what) {
  if (progress)
    progress->stage(what);
}

// The stages of run_case; its locals (the assembler with its factorization, the locator)
// are freed on return, which run_case's total still counts.
template <class D>
std::unique_ptr<typename D::Run> run_case_stages(CaseSpec spec, const RunOverrides& ov) {
  using Clock = std::chrono::steady_clock;
  auto run = std::make_unique<typename D::Run>();
  D::apply_overrides(spec, ov);
  run->spec = std::move(spec);
  run->spec.newton.linear.progress = ov.progress;
  D d(*run, ov);
  d.tune_linear_solver(run->spec.newton.linear);
  d.check_before_mesh(); // fail fast: nothing is meshed for a case that cannot be solved

  auto t0 = Clock::now();
  announce_stage(ov.progress, "meshing");
  run->mesh = d.mesh();
  run->timings.mesh = seconds_since(t0);
  d.check_mesh(); // before the solve: fail fast (stress surfaces through matter)

  run->problem = d.build_problem();
  t0 = Clock::now();
  announce_stage(ov.progress, "assembly: " + std::to_string(D::n_elements(run->mesh)) + " " +
                                  D::element_name + ", order " + std::to_string(run->spec.order));
  run->dofs = std::make_unique<typename D::DofMap>(run->mesh, run->spec.order);
  d.prepare_dofs();
  typename D::Assembler assembler = d.make_assembler();
  run->free_unknowns = assembler.n_unknowns();
  d.prepare_solver(assembler);
  const double setup = seconds_since(t0);

  Eigen::VectorXd u;
  run->report = d.solve(assembler, u);
  run->timings.assemble = setup + run->report.assemble_s;
  run->timings.solve = run->report.solve_s;
  if (!run->report.converged)
    throw SolveError("the solver did not converge: " + run->report.message);
  if (!d.post_processes())
    return run;
  check_finite(u, "solution");

  t0 = Clock::now();
  announce_stage(ov.progress, "post-processing");
  run->field = std::make_unique<typename D::Field>(run->problem, *run->dofs, assembler.expand(u));
  std::vector<std::string> names;
  for (const auto& r : run->spec.regions)
    names.push_back(r.name);
  d.recover(); // first: the 3D energy summary takes its peak |B| from the recovery
  run->energy = d.summarize_energy(names);
  const typename D::Locator locator = d.probe_locator();
  for (const auto& probe : run->spec.probes)
    run->probes.push_back(d.sample_probe(locator, probe));
  for (const auto& section : run->spec.sections)
    run->sections.push_back(d.integrate_section(section));
  check_sections_inside(run->sections, run->spec);
  run->forces = d.forces();
  d.coil_results(assembler, u);
  // Every solve says how accurate it is (issue 29): the energy-norm estimate (3D: and one
  // for each stress-tensor force).
  const auto t_estimate = Clock::now();
  d.estimate_error();
  run->timings.error_estimate = seconds_since(t_estimate);
  d.check_finite_fields();
  check_finite(D::total_energy(*run), "magnetic energy");
  check_forces_finite(run->forces);
  d.scale_to_whole_device();
  run->warnings = d.mesh_warnings();
  for (auto& w : bh_extrapolation_warnings(run->spec.regions, run->energy.regions))
    run->warnings.push_back(std::move(w));
  // Every magnet against its grade's knee (a warning for each at risk).
  run->demagnetization = check_demagnetization(*run->field, run->spec, run->warnings);
  run->timings.postprocess = seconds_since(t0);
  return run;
}

// One case end to end. timings.total includes freeing the solver's factorization and the
// other working data (tens of ms for a large direct factorization on a loaded machine), so
// that the total is the pipeline's whole cost: the Python call overhead is measured against it
// (scripts/benchmark_python.py).
template <class D>
std::unique_ptr<typename D::Run> run_case(CaseSpec spec, const RunOverrides& ov) {
  const auto t_start = std::chrono::steady_clock::now();
  auto run = run_case_stages<D>(std::move(spec), ov);
  run->timings.total = seconds_since(t_start);
  return run;
}

} // namespace magfem
