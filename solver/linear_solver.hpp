#pragma once
// Sparse symmetric positive definite solves. CHOLMOD (supernodal Cholesky) is the default for
// systems whose factor is affordable (2D, axisymmetric, small 3D); above that, conjugate
// gradients preconditioned by two-level p-multigrid (P2 tetrahedra), algebraic multigrid
// (hypre BoomerAMG or PETSc GAMG, through PETSc) or incomplete Cholesky. `automatic` picks
// by size and element order. The symbolic analysis is done
// once per pattern and reused for every Newton step.
//
// Every Krylov solve checks its own result: a stop on anything but the tolerance, and a true
// residual |b - A x| / |b| that does not confirm it, throw SolveError. Never a silently wrong
// field.
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solver/tangent_solver.hpp"

namespace magfem {

class Progress;
struct KrylovOutcome;   // petsc_solver.hpp
struct DistributedRows; // distributed_rows.hpp

enum class LinearSolverKind { automatic, cholmod, cg };
enum class PreconditionerKind { automatic, ichol, boomeramg, gamg, pmg };

struct LinearSolverOptions {
  LinearSolverKind kind = LinearSolverKind::automatic;
  // automatic: CHOLMOD up to this many unknowns, CG above.
  int direct_limit = 1'500'000;
  // automatic: and only if a quick symbolic analysis (AMD ordering) predicts at most this
  // many floating-point operations for the factorization (10^9). 3D systems fill in far
  // more than 2D ones: a 237k-unknown P2 tet system needs 870 GFlop and 2.7 GB, i.e. 11
  // minutes with Debian's reference BLAS (1.3 GFlop/s here), while CG+IC takes 20 s.
  // 0 = no limit.
  double direct_max_gflop = 20;
  // Relative residual. A decade below Newton's residual tolerance (1e-9); measured on the
  // 32-magnet benchmark (633k unknowns): the field at r56 moves by at most 1e-9 T from a
  // solve to 1e-12, which takes 22 CG iterations against 18.
  double cg_tolerance = 1e-10;
  int cg_max_iterations = 20000;
  // CG's preconditioner. automatic: p-multigrid when a coarse space is given (P2 tetrahedra,
  // coarse_prolongation) and no petsc_options; else BoomerAMG from amg_min_unknowns on (or
  // whenever petsc_options are given), incomplete Cholesky below. A pmg or AMG solve that
  // fails falls back to incomplete Cholesky with a note. A named preconditioner gets no
  // fallback: its failure is the solver's. Why pmg (magnetized sphere, 255k / 488k / 942k
  // unknowns, end to end on 2 shared cores): 23 / 23 / 23 CG iterations and 8.2 / 13.7 /
  // 34.6 s against incomplete Cholesky's 332 / 486 / 503 and 14.2 / 40.1 / 115.5 s;
  // benchmark32 at 957k: 23 iterations, 41 s against 424 and 107 s.
  PreconditionerKind preconditioner = PreconditionerKind::automatic;
  // Off by default (AMG only when asked for): on our P2 systems with the open-boundary shell
  // AMG was measured slower than incomplete Cholesky (magnetized sphere, 228k unknowns, to
  // 1e-12: IC 403 iterations / 33 s; BoomerAMG HMIS ext+i 127 / 54 s; PETSc GAMG 212 / 65 s,
  // 2 shared cores), and its iterations grew under refinement (78 -> 115 from 248k to 308k).
  int amg_min_unknowns = std::numeric_limits<int>::max();
  std::string petsc_options; // e.g. "-pc_type gamg", passed through to PETSc
  // pmg (two-level p-multigrid, automatic when given): interpolation from the coarse space to
  // the unknowns (for P2 tetrahedra the P1 functions on the same mesh,
  // solver/p1_coarse_space.hpp). Without one (P1, 2D) there is no coarser order and pmg is
  // BoomerAMG on the system itself.
  std::shared_ptr<const Eigen::SparseMatrix<double, Eigen::RowMajor>> coarse_prolongation;
  // pmg: equations its smoother solves together (the open-boundary shell's), sorted.
  std::shared_ptr<const std::vector<int>> smoother_block;
  // Distributed runs only: the rows each process owns, decided before assembly (own-row
  // assembly, distributed_rows.hpp); null: the rows are decided from the assembled parts.
  std::shared_ptr<const DistributedRows> distributed_rows;
  Progress* progress = nullptr; // not owned; null = silent
};

// Why PETSc would refuse options.petsc_options for options.preconditioner, "" if it accepts
// them (petsc_solver.hpp). For the case reader.
std::string petsc_options_problem(const LinearSolverOptions& options);

// The largest true residual |b - A x| / |b| that still confirms a Krylov solve stopped on
// relative tolerance `tol`: the recursively updated residual drifts from the true one by
// about machine precision times the condition number (for iron at mu_r 1e4 meshed finely
// 1e-7); above this bound the iteration stopped on something else.
double true_residual_limit(double tol);
// "<method> did not converge: stopped after ... iterations (<reason>) at relative residual
// ...; the tolerance is ...": the message of a Krylov solve that failed.
std::string describe_krylov_stop(const KrylovOutcome& outcome, const std::string& method,
                                 double tol);

class LinearSolver final : public TangentSolver {
public:
  explicit LinearSolver(LinearSolverOptions options = {});
  ~LinearSolver() override;
  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;

  // `lower`: symmetric matrix given by its lower triangle; it must outlive the solve() calls
  // that follow. Throws SolveError if it is not positive definite (a floating region without
  // a gauge, a bad material) or the preconditioner cannot be built.
  void factorize(const Eigen::SparseMatrix<double>& lower) override;
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) override;
  // One solution per column of `rhs`, with the factorization or preconditioner set up once:
  // CHOLMOD solves all columns in one pass over its factor; CG + pmg runs the columns side by
  // side with each V-cycle applied to all at once (PetscSolver::solve_many). Each column is
  // checked as solve() checks its one. last_iterations(): the largest column's count.
  Eigen::MatrixXd solve_many(const Eigen::MatrixXd& rhs) override;
  // Krylov solves from now on stop at this relative residual (LinearSolverOptions::
  // cg_tolerance until then); direct solves are exact whatever it is.
  void set_cg_tolerance(double tol) override;
  double cg_tolerance() const { return options_.cg_tolerance; }
  std::string name() const override;           // cholmod | cg
  std::string preconditioner() const override; // none (direct) | ichol | boomeramg | gamg | pmg
  int last_iterations() const override { return last_iterations_; }
  // Seconds spent so far in factorize() (factorization, preconditioner set-up) and solve().
  double setup_seconds() const override { return setup_s_; }
  double solve_seconds() const override { return solve_s_; }
  // Why the automatic choice changed course (AMG fallback), for the console and summary.
  const std::vector<std::string>& notes() const override { return notes_; }
  // pmg with a smoother block: how many times the block was factorized (it is reused while
  // its entries do not change, e.g. the open-boundary shell across Newton steps); 0 otherwise.
  int smoother_block_factorizations() const;
  // Factorization cost predicted by the automatic choice (0 if it did not look).
  double predicted_gflop() const { return predicted_gflop_; }
  double predicted_factor_gb() const { return predicted_factor_gb_; }

private:
  struct Impl;
  void choose(const Eigen::SparseMatrix<double>& lower);
  void set_up_krylov(const Eigen::SparseMatrix<double>& lower);
  Eigen::VectorXd solve_krylov(const Eigen::VectorXd& rhs);
  std::string krylov_failure(const KrylovOutcome& o, const Eigen::VectorXd& rhs,
                             const Eigen::VectorXd& x, const std::string& method) const;
  void fall_back(const std::string& why);

  std::unique_ptr<Impl> impl_;
  LinearSolverOptions options_;
  int last_iterations_ = 1;
  double setup_s_ = 0, solve_s_ = 0;
  std::vector<std::string> notes_;
  double predicted_gflop_ = 0, predicted_factor_gb_ = 0;
};

} // namespace magfem
