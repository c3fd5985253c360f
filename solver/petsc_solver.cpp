#include "solver/petsc_solver.hpp"

#include "solver/petsc_backend.hpp"

// PetscSolver is a handle on the module's solver (petsc_backend.hpp); PETSc itself is
// serialized inside the module.
namespace magfem {

void start_petsc(bool any_thread_calls_mpi) {
  petsc_backend().start_petsc(any_thread_calls_mpi);
}

std::string petsc_options_problem(const PetscSolverOptions& options) {
  return petsc_backend().petsc_options_problem(options);
}

DistributedRows
partition_distributed_rows(const Eigen::SparseMatrix<double>& vertex_pattern,
                           const Eigen::SparseMatrix<double, Eigen::RowMajor>& prolongation,
                           const std::vector<int>* smoother_block) {
  return petsc_backend().partition_distributed_rows(vertex_pattern, prolongation, smoother_block);
}

PetscSolver::PetscSolver(PetscSolverOptions options)
    : engine_(petsc_backend().make_solver(std::move(options))) {}

PetscSolver::~PetscSolver() = default;

void PetscSolver::setup(const Eigen::SparseMatrix<double>& lower) {
  engine_->setup(lower);
}

KrylovOutcome PetscSolver::solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) {
  return engine_->solve(rhs, x);
}

std::vector<KrylovOutcome> PetscSolver::solve_many(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& x) {
  return engine_->solve_many(rhs, x);
}

void PetscSolver::set_relative_tolerance(double tol) {
  engine_->set_relative_tolerance(tol);
}

void PetscSolver::begin_distributed(const Eigen::SparseMatrix<double>& lower_pattern) {
  engine_->begin_distributed(lower_pattern);
}

void PetscSolver::add_lower_share(const Eigen::SparseMatrix<double>& lower) {
  engine_->add_lower_share(lower);
}

void PetscSolver::setup_distributed() {
  engine_->setup_distributed();
}
void PetscSolver::assemble_own_rows(const Eigen::SparseMatrix<double>& lower) {
  engine_->assemble_own_rows(lower);
}

KrylovOutcome PetscSolver::solve_distributed(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) {
  return engine_->solve_distributed(rhs, x);
}

std::string PetscSolver::preconditioner_name() const {
  return engine_->preconditioner_name();
}

int PetscSolver::block_factorizations() const {
  return engine_->block_factorizations();
}

} // namespace magfem
