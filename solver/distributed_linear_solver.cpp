#include "solver/distributed_linear_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "core/input_error.hpp"
#include "core/progress.hpp"

namespace magfem {
namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The preconditioner a distributed solve uses for the one the case asks for, and the note
// that says what ran. p-multigrid (asked for, or the automatic choice for P2 tetrahedra
// without petsc_options, as serially) runs distributed with a smoother that differs from the
// serial one across the processes (petsc_ksp_solver.cpp): the note says so. The
// factorizations (CHOLMOD, incomplete Cholesky), which run on one process only, become
// p-multigrid where there is a coarse space and BoomerAMG where not, with a note.
std::string distributed_preconditioner(const LinearSolverOptions& o, int size,
                                       std::vector<std::string>& notes) {
  const bool cg = o.kind != LinearSolverKind::cholmod;
  if (cg && o.preconditioner == PreconditionerKind::gamg)
    return "gamg";
  if (cg && o.preconditioner == PreconditionerKind::boomeramg)
    return "boomeramg";
  const std::string over = "distributed over " + std::to_string(size) + " processes: ";
  const bool coarse_space = o.coarse_prolongation != nullptr;
  auto note = [&](const std::string& text) {
    notes.push_back(over + text);
    if (o.progress)
      o.progress->note(notes.back());
  };
  const bool shell = o.smoother_block && !o.smoother_block->empty();
  const std::string pmg =
      "CG + p-multigrid on a partition of the mesh, smoothed by " +
      std::string(shell ? "Gauss-Seidel over all processes' rows, process after process where "
                          "they meet (the open-boundary shell whole on process 0, by Cholesky)"
                        : "symmetric Gauss-Seidel over all processes' rows, process after "
                          "process where they meet") +
      std::string(o.distributed_rows ? "; each process assembled the tetrahedra of its own rows"
                                     : "");
  const bool automatic_pmg = cg && o.preconditioner == PreconditionerKind::automatic &&
                             coarse_space && o.petsc_options.empty();
  if ((cg && o.preconditioner == PreconditionerKind::pmg && coarse_space) || automatic_pmg) {
    note(pmg);
    return "pmg";
  }
  if (cg && o.preconditioner == PreconditionerKind::pmg) {
    note("CG + BoomerAMG in place of p-multigrid, which needs P2 tetrahedra (no coarser "
         "order here)");
    return "boomeramg";
  }
  std::string asked = "the automatic choice (CHOLMOD or incomplete Cholesky)";
  if (o.kind == LinearSolverKind::cholmod)
    asked = "CHOLMOD";
  else if (o.preconditioner == PreconditionerKind::ichol)
    asked = "incomplete Cholesky";
  if (coarse_space && o.petsc_options.empty()) {
    note(pmg + " in place of " + asked + ", which runs on one process only");
    return "pmg";
  }
  note("CG + BoomerAMG in place of " + asked + ", which runs on one process only");
  return "boomeramg";
}

PetscSolverOptions petsc_options(const LinearSolverOptions& o, int size,
                                 std::vector<std::string>& notes) {
  return PetscSolverOptions{distributed_preconditioner(o, size, notes),
                            o.petsc_options,
                            o.cg_tolerance,
                            o.cg_max_iterations,
                            o.progress,
                            o.coarse_prolongation.get(),
                            o.smoother_block.get(),
                            o.distributed_rows.get()};
}

} // namespace

bool distributed_runs_pmg(const LinearSolverOptions& options) {
  LinearSolverOptions quiet = options;
  quiet.progress = nullptr;
  std::vector<std::string> notes;
  return distributed_preconditioner(quiet, 2, notes) == "pmg";
}

DistributedLinearSolver::DistributedLinearSolver(const LinearSolverOptions& options, int size)
    : coarse_prolongation_(options.coarse_prolongation), smoother_block_(options.smoother_block),
      rows_(options.distributed_rows), tolerance_(options.cg_tolerance),
      solver_(petsc_options(options, size, notes_)) {}

void DistributedLinearSolver::factorize(const Eigen::SparseMatrix<double>& lower_part) {
  load(lower_part);
  set_up();
}

void DistributedLinearSolver::load(const Eigen::SparseMatrix<double>& lower_part) {
  const auto t0 = Clock::now();
  if (rows_) {
    // Own-row assembly: the part holds this process's rows whole; only they are set.
    solver_.assemble_own_rows(lower_part);
  } else {
    // The part has the whole pattern (Assembler3D's), which gives the exact preallocation.
    solver_.begin_distributed(lower_part);
    solver_.add_lower_share(lower_part);
  }
  setup_s_ += seconds_since(t0);
}

void DistributedLinearSolver::set_up() {
  const auto t0 = Clock::now();
  solver_.setup_distributed();
  setup_s_ += seconds_since(t0);
}

Eigen::VectorXd DistributedLinearSolver::solve(const Eigen::VectorXd& rhs) {
  const auto t0 = Clock::now();
  Eigen::VectorXd x;
  const KrylovOutcome o = solver_.solve_distributed(rhs, x);
  solve_s_ += seconds_since(t0);
  last_iterations_ = o.iterations;
  last_true_residual_ = o.true_relative_residual;
  const std::string method = "CG + " + solver_.preconditioner_name();
  if (!o.converged)
    throw SolveError(describe_krylov_stop(o, method, tolerance_));
  if (o.true_relative_residual > true_residual_limit(tolerance_)) {
    char buf[120];
    std::snprintf(buf, sizeof buf, "; the true residual |b - A x| / |b| is %.3e",
                  o.true_relative_residual);
    throw SolveError(describe_krylov_stop(o, method, tolerance_) + buf);
  }
  return x;
}

Eigen::MatrixXd DistributedLinearSolver::solve_many(const Eigen::MatrixXd& rhs) {
  Eigen::MatrixXd x(rhs.rows(), rhs.cols());
  int most = 0;
  for (Eigen::Index j = 0; j < rhs.cols(); ++j) {
    x.col(j) = solve(rhs.col(j));
    most = std::max(most, last_iterations_);
  }
  last_iterations_ = most;
  return x;
}

void DistributedLinearSolver::set_cg_tolerance(double tol) {
  tolerance_ = tol;
  solver_.set_relative_tolerance(tol);
}

} // namespace magfem
