#pragma once
// Conjugate gradients preconditioned by algebraic multigrid (hypre BoomerAMG or PETSc GAMG),
// or by two-level p-multigrid (pmg: a symmetric Gauss-Seidel smoother on the system, BoomerAMG on
// the Galerkin coarse operator P^T A P of a given coarse space), through PETSc. This header keeps
// PETSc out of every other translation unit: its types live behind Impl in petsc_solver.cpp, the
// only file that includes PETSc. PETSc (and MPI) start on the first use in a process and stop at
// its exit.
#include <memory>
#include <string>

#include <Eigen/SparseCore>

namespace magfem {

class Progress;

struct PetscSolverOptions {
  std::string preconditioner = "boomeramg"; // boomeramg | gamg | pmg
  std::string petsc_options;                // passed to PETSc last: wins over ours
  double relative_tolerance = 1e-12;        // |b - A x| / |b| (unpreconditioned)
  int max_iterations = 20000;
  Progress* progress = nullptr; // not owned; null = silent
  // pmg: interpolation from the coarse space (rows: the system's unknowns, columns: coarse
  // unknowns). Copied by setup(); required for pmg.
  const Eigen::SparseMatrix<double, Eigen::RowMajor>* prolongation = nullptr;
};

// How a Krylov solve ended. `converged` only when it stopped on the tolerance.
struct KrylovOutcome {
  bool converged = false;
  int iterations = 0;
  double relative_residual = 0; // as the Krylov method last saw it
  std::string reason;           // PETSc's name for the stop (e.g. CONVERGED_RTOL, DIVERGED_ITS)
};

class PetscSolver {
public:
  explicit PetscSolver(PetscSolverOptions options);
  ~PetscSolver();
  PetscSolver(const PetscSolver&) = delete;
  PetscSolver& operator=(const PetscSolver&) = delete;

  // Copies the symmetric matrix given by its lower triangle into a PETSc AIJ matrix and sets up
  // the preconditioner. Throws SolveError when PETSc refuses (bad options, set-up failure).
  void setup(const Eigen::SparseMatrix<double>& lower);
  KrylovOutcome solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x);
  // The preconditioner actually in use (the options may have changed it): boomeramg, gamg,
  // or PETSc's name for another one.
  std::string preconditioner_name() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Why PETSc would refuse `options.petsc_options` (their form: -name [value] pairs; a value or
// a type name it does not know), or "" if it accepts them. Sets the preconditioner up with
// them on a small system to find out (pmg: with a coarse space of its own). Lets the case
// reader call a bad option an input error rather than a solver failure.
std::string petsc_options_problem(const PetscSolverOptions& options);

} // namespace magfem
