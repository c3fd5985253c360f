#pragma once
// Inside the PETSc module (petsc_backend.hpp): PetscSolver's implementation over PETSc's KSP,
// and the start of PETSc (with MPI) for the process. Only module sources include this.
#include <memory>
#include <string>

#include "solver/petsc_backend.hpp"

namespace magfem::petsc_module {

// start_petsc and petsc_options_problem of petsc_solver.hpp.
void start_petsc(bool any_thread_calls_mpi);
std::string petsc_options_problem(const PetscSolverOptions& options);

class PetscKspSolver final : public PetscSolverEngine {
public:
  explicit PetscKspSolver(PetscSolverOptions options);
  ~PetscKspSolver() override;
  PetscKspSolver(const PetscKspSolver&) = delete;
  PetscKspSolver& operator=(const PetscKspSolver&) = delete;

  void setup(const Eigen::SparseMatrix<double>& lower) override;
  KrylovOutcome solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) override;
  std::vector<KrylovOutcome> solve_many(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& x) override;
  void set_relative_tolerance(double tol) override;
  void begin_distributed(const Eigen::SparseMatrix<double>& lower_pattern) override;
  void add_lower_share(const Eigen::SparseMatrix<double>& lower) override;
  void setup_distributed() override;
  void assemble_own_rows(const Eigen::SparseMatrix<double>& lower) override;
  KrylovOutcome solve_distributed(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) override;
  std::string preconditioner_name() const override;
  int block_factorizations() const override;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace magfem::petsc_module
