#include "solver/distributed_solve3d.hpp"

#include <array>
#include <chrono>
#include <cstdio>

#include "core/input_error.hpp"
#include "core/progress.hpp"
#include "solver/petsc_solver.hpp"

namespace magfem {
namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The preconditioner a distributed solve uses for the one the case asks for, and the note
// that says so when they differ. Incomplete Cholesky and CHOLMOD are factorizations of the
// whole matrix on one process; p-multigrid's coarse space (P1 interpolation) is built whole
// on one process too. Rather than refuse a case that runs serially, these become BoomerAMG,
// the preconditioner hypre distributes natively, and the summary says so.
std::string distributed_preconditioner(const LinearSolverOptions& o, int size,
                                       std::vector<std::string>& notes) {
  if (o.kind != LinearSolverKind::cholmod) {
    if (o.preconditioner == PreconditionerKind::gamg)
      return "gamg";
    if (o.preconditioner == PreconditionerKind::boomeramg)
      return "boomeramg";
  }
  std::string asked = "the automatic choice (CHOLMOD or incomplete Cholesky)";
  if (o.kind == LinearSolverKind::cholmod)
    asked = "CHOLMOD";
  else if (o.preconditioner == PreconditionerKind::ichol)
    asked = "incomplete Cholesky";
  else if (o.preconditioner == PreconditionerKind::pmg)
    asked = "p-multigrid";
  notes.push_back("distributed over " + std::to_string(size) + " processes: CG + BoomerAMG in " +
                  "place of " + asked + ", which runs on one process only");
  return "boomeramg";
}

} // namespace

ElementRange element_share(std::size_t n_elements, int rank, int size) {
  const auto r = static_cast<std::size_t>(rank), s = static_cast<std::size_t>(size);
  const std::size_t base = n_elements / s, extra = n_elements % s;
  const std::size_t first = r * base + std::min(r, extra);
  return {first, first + base + (r < extra ? 1 : 0)};
}

NewtonReport solve_linear_distributed(const Assembler3D& assembler, const DofMap3D& dofs,
                                      std::size_t n_elements, int rank, int size,
                                      const LinearSolverOptions& options, Eigen::VectorXd& u) {
  if (!assembler.is_linear())
    throw SolveError("internal: a distributed solve of a nonlinear system");
  NewtonReport report;
  report.linear = true;
  report.linear_solver = "cg";
  const std::string preconditioner = distributed_preconditioner(options, size, report.notes);
  Progress* progress = options.progress;
  for (const auto& note : report.notes)
    if (progress)
      progress->note(note);

  auto t0 = Clock::now();
  PetscSolver solver(PetscSolverOptions{preconditioner, options.petsc_options, options.cg_tolerance,
                                        options.cg_max_iterations, progress, nullptr});
  solver.begin_distributed(assembler.pattern().zero_matrix());
  const ElementRange mine = element_share(n_elements, rank, size);
  if (progress)
    progress->stage("assembly: " + std::to_string(mine.last - mine.first) + " of " +
                    std::to_string(n_elements) + " tetrahedra on each of " + std::to_string(size) +
                    " processes");
  // A linear system: K phi = f with f = -r(0), the element residuals at phi = 0 (the
  // remanence), K the element tangents.
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(dofs.n_dofs());
  const int n = dofs.dofs_per_element();
  const std::vector<int>& dof_to_eq = assembler.dof_to_equation();
  std::array<double, 10> re{}, eq_rhs{};
  std::array<double, 100> ke{};
  std::array<int, 10> eq{};
  for (std::size_t t = mine.first; t < mine.last; ++t) {
    assembler.element(t, zero, re.data(), ke.data(), TangentKind::newton);
    const int* dof = dofs.element_dofs(t);
    for (int i = 0; i < n; ++i) {
      eq[i] = dof_to_eq[dof[i]];
      eq_rhs[i] = -re[i];
    }
    solver.add_element(n, eq.data(), ke.data(), eq_rhs.data());
  }
  report.assemble_s = seconds_since(t0);

  t0 = Clock::now();
  if (progress)
    progress->stage("preconditioner set-up: " + preconditioner + ", " +
                    std::to_string(assembler.n_unknowns()) + " unknowns on " +
                    std::to_string(size) + " processes");
  solver.setup_distributed();
  report.linear_setup_s = seconds_since(t0);
  report.preconditioner = solver.preconditioner_name();

  t0 = Clock::now();
  if (progress)
    progress->stage("solve: CG + " + report.preconditioner);
  const KrylovOutcome o = solver.solve_distributed(u);
  report.linear_solve_s = seconds_since(t0);
  report.solve_s = report.linear_setup_s + report.linear_solve_s;
  report.iterations = 1;
  report.linear_iterations = o.iterations;
  const std::string method = "CG + " + report.preconditioner;
  if (!o.converged)
    throw SolveError(describe_krylov_stop(o, method, options.cg_tolerance));
  if (o.true_relative_residual > true_residual_limit(options.cg_tolerance)) {
    char buf[120];
    std::snprintf(buf, sizeof buf, "; the true residual |b - A x| / |b| is %.3e",
                  o.true_relative_residual);
    throw SolveError(describe_krylov_stop(o, method, options.cg_tolerance) + buf);
  }
  // As for a serial linear solve: the initial relative residual (1, or 0 without sources)
  // and the final one, here the true residual PETSc computed.
  const bool sourceless = assembler.load_norm() == 0;
  report.residual_history = {sourceless ? 0.0 : 1.0, o.true_relative_residual};
  report.step_lengths = {1.0};
  report.converged = true;
  if (sourceless)
    report.message = "no sources: zero field";
  return report;
}

} // namespace magfem
