#pragma once
// Conjugate gradients preconditioned by algebraic multigrid (hypre BoomerAMG or PETSc GAMG),
// or by two-level p-multigrid (pmg: a symmetric Gauss-Seidel smoother on the system, BoomerAMG on
// the Galerkin coarse operator P^T A P of a given coarse space), through PETSc. This header keeps
// PETSc out of every other translation unit: PETSc is called only from the module
// libmagfem_petsc.so (petsc_backend.hpp), which the first PetscSolver, start_petsc or
// petsc_options_problem of a process opens. PETSc (and MPI) start on the first use in a
// process, or at the start of a run under mpirun (start_petsc), and stop at its exit.
//
// Two ways to give it the system: setup() copies a whole matrix held by this process into a
// sequential PETSc matrix; the distributed mode (begin_distributed, add_lower_share,
// setup_distributed, solve_distributed) builds one PETSc MPIAIJ matrix over MPI_COMM_WORLD
// from the contributions each process assembled for its share of the elements.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/SparseCore>

#include "solver/distributed_rows.hpp"

namespace magfem {

class Progress;
class PetscSolverEngine;

struct PetscSolverOptions {
  std::string preconditioner = "boomeramg"; // boomeramg | gamg | pmg
  std::string petsc_options;                // passed to PETSc last: wins over ours
  double relative_tolerance = 1e-10;        // |b - A x| / |b| (unpreconditioned)
  int max_iterations = 20000;
  Progress* progress = nullptr; // not owned; null = silent
  // pmg: interpolation from the coarse space (rows: the system's unknowns, columns: coarse
  // unknowns). Copied by setup(); required for pmg.
  const Eigen::SparseMatrix<double, Eigen::RowMajor>* prolongation = nullptr;
  // pmg: equations (sorted) that the fine-level smoother solves together by a sparse
  // Cholesky factorization (the open-boundary shell); empty = none.
  const std::vector<int>* smoother_block = nullptr;
  // Distributed pmg: the rows each process owns, decided before assembly
  // (partition_distributed_rows); null: begin_distributed partitions the given pattern.
  const DistributedRows* rows = nullptr;
  // Serial pmg with a smoother block and no petsc_options: factorize the block on a thread of
  // its own during the rest of the set-up (petsc_ksp_solver.cpp). false: when PETSc sets the
  // smoother up, after the coarse operator (tests compare the two).
  bool concurrent_block_factor = true;
  // Serial pmg and no petsc_options: CG's and PCMG's products with the system matrix on all
  // cores (petsc_ksp_solver.cpp) rather than PETSc's serial one. false: PETSc's (tests).
  bool threaded_product = true;
};

// How a Krylov solve ended. `converged` only when it stopped on the tolerance.
struct KrylovOutcome {
  bool converged = false;
  int iterations = 0;
  double relative_residual = 0; // as the Krylov method last saw it
  std::string reason;           // PETSc's name for the stop (e.g. CONVERGED_RTOL, DIVERGED_ITS)
  // |b - A x| / |b| computed by PETSc after the solve (distributed solves, where no process
  // holds A to check it); -1 when not computed.
  double true_relative_residual = -1;
};

// Starts PETSc and MPI for the rest of the process (no-op once started). With
// `any_thread_calls_mpi`, MPI is asked for MPI_THREAD_MULTIPLE (a sweep under mpirun: one
// thread deals positions while others solve); otherwise PETSc's default, MPI_THREAD_FUNNELED.
void start_petsc(bool any_thread_calls_mpi = false);

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
  // Every column of `rhs` with the preconditioner set up once by setup(), one outcome per
  // column (x: the solutions, column for column). pmg with a smoother block (as our 3D open
  // boundary has) runs the columns' CGs side by side with a V-cycle applied to all columns
  // at once (simultaneous_pcg.hpp); any other preconditioner, or petsc_options that could
  // change the cycle, runs one CG per column.
  std::vector<KrylovOutcome> solve_many(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& x);
  // The relative tolerance of the next solves (inexact Newton loosens it far from the
  // solution); takes effect at once, set-up or not.
  void set_relative_tolerance(double tol);

  // Distributed mode; every process of MPI_COMM_WORLD calls these collective steps in this
  // order (add_lower_share is local). Rows are owned in contiguous blocks, PETSc's default split
  // (the first n % size processes own one row more). `lower_pattern`: the lower triangle of
  // the whole system's sparsity (values unused), the same on every process; it gives the exact
  // preallocation of this process's rows. pmg: every process gives the whole interpolation
  // and smoother block (options); each uses its own rows of them.
  void begin_distributed(const Eigen::SparseMatrix<double>& lower_pattern);
  // Adds this process's part of the symmetric matrix, given by its lower triangle (the whole
  // system's size; what this process's elements contributed, zero elsewhere). Its non-zero
  // entries in rows of other processes are stashed and sent to them by setup_distributed().
  void add_lower_share(const Eigen::SparseMatrix<double>& lower);
  // Collective: completes the assembly (off-process entries travel here) and sets up CG and
  // the preconditioner. Throws SolveError as setup() does.
  void setup_distributed();
  // Own-row assembly (distributed_rows.hpp), in place of begin_distributed and
  // add_lower_share: `lower` is this process's lower triangle (the whole system's size) with
  // the complete entries of the rows it owns (options.rows, required); only those are set.
  // Collective; setup_distributed() follows.
  void assemble_own_rows(const Eigen::SparseMatrix<double>& lower);
  // Collective: CG on the assembled system from x = 0 for the right-hand side `rhs` (the whole
  // vector, the same on every process; each takes its own rows); fills
  // true_relative_residual. `x` receives the whole solution on every process. May be called
  // again with another right-hand side: the preconditioner set-up is reused.
  KrylovOutcome solve_distributed(const Eigen::VectorXd& rhs, Eigen::VectorXd& x);
  // The preconditioner actually in use (the options may have changed it): boomeramg, gamg,
  // or PETSc's name for another one.
  std::string preconditioner_name() const;
  // pmg with a smoother block: how many times its block was factorized. setup() again with a
  // block whose entries did not change (Newton: the shell is air) reuses the factorization.
  int block_factorizations() const;

private:
  std::unique_ptr<PetscSolverEngine> engine_; // in the PETSc module
};

// Collective over MPI_COMM_WORLD: the rows of a distributed p-multigrid system each process
// owns (pmg_partition.hpp), from the P1 graph (vertex_coupling_pattern), the interpolation
// from the P1 unknowns and the smoother block (or null), all the same on every process.
DistributedRows
partition_distributed_rows(const Eigen::SparseMatrix<double>& vertex_pattern,
                           const Eigen::SparseMatrix<double, Eigen::RowMajor>& prolongation,
                           const std::vector<int>* smoother_block);

// Why PETSc would refuse `options.petsc_options` (their form: -name [value] pairs; a value or
// a type name it does not know), or "" if it accepts them. Sets the preconditioner up with
// them on a small system to find out (pmg: with a coarse space of its own). Lets the case
// reader call a bad option an input error rather than a solver failure.
std::string petsc_options_problem(const PetscSolverOptions& options);

} // namespace magfem
