#pragma once
// CG with p-multigrid, BoomerAMG or GAMG over the processes of an mpirun (MPI_COMM_WORLD): the
// tangent solver of a distributed solve. Each process passes to factorize() the part of the
// matrix its elements contributed (DistributedSystem3D), PETSc adds the parts into one MPIAIJ
// matrix (rows owned in contiguous blocks) and sets the preconditioner up once; every solve()
// takes the whole right-hand side, the same on every process, and returns the whole solution
// on every process. All methods but the accessors are collective.
//
// p-multigrid (P2 tetrahedra: options.coarse_prolongation given, the same on every process)
// runs distributed, with the serial smoother's sweeps over all processes' rows (a note says so).
// Incomplete Cholesky and CHOLMOD, which factor the whole matrix on one process, become
// p-multigrid where there is a coarse space and BoomerAMG where not, with a note.
#include <memory>
#include <string>
#include <vector>

#include "solver/linear_solver.hpp"
#include "solver/petsc_solver.hpp"
#include "solver/tangent_solver.hpp"

namespace magfem {

// Whether a distributed solve with these options runs p-multigrid (the coarse space set, no
// option asking for another preconditioner): then its rows are a partition of the mesh,
// which own-row assembly decides before assembly (distributed_rows.hpp).
bool distributed_runs_pmg(const LinearSolverOptions& options);

class DistributedLinearSolver final : public TangentSolver {
public:
  // `size`: the processes (for the note).
  DistributedLinearSolver(const LinearSolverOptions& options, int size);

  // load(lower_part), then set_up().
  void factorize(const Eigen::SparseMatrix<double>& lower_part) override;
  // The two halves of factorize: the part into the distributed matrix (PETSc keeps its own
  // copy, so the caller may free the part before the set-up, the peak of a process's memory),
  // and the preconditioner's set-up on it.
  void load(const Eigen::SparseMatrix<double>& lower_part);
  void set_up();
  // Throws SolveError, on every process alike, when CG stops short of the tolerance or the
  // true residual does not confirm it.
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) override;
  // One CG per column with the one preconditioner set-up; last_iterations(): the largest.
  Eigen::MatrixXd solve_many(const Eigen::MatrixXd& rhs) override;
  void set_cg_tolerance(double tol) override;
  std::string name() const override { return "cg"; }
  std::string preconditioner() const override { return solver_.preconditioner_name(); }
  int last_iterations() const override { return last_iterations_; }
  double setup_seconds() const override { return setup_s_; }
  double solve_seconds() const override { return solve_s_; }
  const std::vector<std::string>& notes() const override { return notes_; }
  // |b - A x| / |b| of the last solve, as PETSc computed it over the distributed matrix.
  double last_true_residual() const { return last_true_residual_; }

private:
  std::vector<std::string> notes_; // before solver_: its options name the preconditioner
  // Kept alive for solver_, which points at them.
  std::shared_ptr<const Eigen::SparseMatrix<double, Eigen::RowMajor>> coarse_prolongation_;
  std::shared_ptr<const std::vector<int>> smoother_block_;
  std::shared_ptr<const DistributedRows> rows_;
  double tolerance_;
  PetscSolver solver_;
  int last_iterations_ = 0;
  double last_true_residual_ = 0;
  double setup_s_ = 0, solve_s_ = 0;
};

} // namespace magfem
