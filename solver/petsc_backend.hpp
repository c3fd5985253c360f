#pragma once
// The PETSc and MPI backend: everything that calls PETSc or MPI lives in the module
// libmagfem_petsc.so (petsc_module.cpp, petsc_ksp_solver.cpp, mpi_world_backend.cpp), which
// the library opens the first time a solve needs the iterative or distributed solver or a run
// under mpirun starts MPI. Why a module: PETSc, Open MPI and hypre are ~100 shared libraries
// whose loading cost every command 50-400 ms of start-up, a 2D solve or an analytic curve
// included (issue 35). PetscSolver (petsc_solver.hpp) and the functions of mpi_context.hpp
// are the callers' interface; they forward to the objects declared here.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "solver/mpi_context.hpp"
#include "solver/petsc_solver.hpp"

namespace magfem {

// One PETSc Krylov solver (PetscSolver's implementation); the methods are PetscSolver's.
class PetscSolverEngine {
public:
  virtual ~PetscSolverEngine() = default;
  virtual void setup(const Eigen::SparseMatrix<double>& lower) = 0;
  virtual KrylovOutcome solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) = 0;
  virtual std::vector<KrylovOutcome> solve_many(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& x) = 0;
  virtual void set_relative_tolerance(double tol) = 0;
  virtual void begin_distributed(const Eigen::SparseMatrix<double>& lower_pattern) = 0;
  virtual void add_lower_share(const Eigen::SparseMatrix<double>& lower) = 0;
  virtual void setup_distributed() = 0;
  virtual void assemble_own_rows(const Eigen::SparseMatrix<double>& lower) = 0;
  virtual KrylovOutcome solve_distributed(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) = 0;
  virtual std::string preconditioner_name() const = 0;
  virtual int block_factorizations() const = 0;
};

// WorkDealer's implementation; the methods are WorkDealer's.
class WorkDealerEngine {
public:
  virtual ~WorkDealerEngine() = default;
  virtual int next(int worker, int finished, const std::string& result) = 0;
  virtual void serve(const std::function<void(int item, const std::string& result)>& on_result) = 0;
};

// What the module provides; the functions are those of the same names in petsc_solver.hpp and
// mpi_context.hpp. One object per process, owned by the module.
class PetscBackend {
public:
  virtual void start_petsc(bool any_thread_calls_mpi) = 0;
  virtual std::unique_ptr<PetscSolverEngine> make_solver(PetscSolverOptions options) = 0;
  virtual std::string petsc_options_problem(const PetscSolverOptions& options) = 0;
  virtual DistributedRows
  partition_distributed_rows(const Eigen::SparseMatrix<double>& vertex_pattern,
                             const Eigen::SparseMatrix<double, Eigen::RowMajor>& prolongation,
                             const std::vector<int>* smoother_block) = 0;
  virtual MpiWorld join_mpi_world(bool any_thread_calls_mpi) = 0;
  virtual MpiWorld started_mpi_world() = 0;
  virtual bool same_on_every_rank(std::uint64_t value) = 0;
  virtual void sum_on_every_rank(double* values, std::size_t n) = 0;
  virtual void union_to_root(float* values, std::size_t n) = 0;
  virtual void idle_barrier() = 0;
  virtual void lend_node_cores_to_root() = 0;
  virtual int code_of_root(int code) = 0;
  virtual void broadcast_bytes(int root, std::string& bytes) = 0;
  virtual std::unique_ptr<WorkDealerEngine> make_work_dealer(std::vector<int> items,
                                                             int workers) = 0;
  virtual void abort_mpi_world(int code) = 0; // returns only if MPI is not distributed

protected:
  ~PetscBackend() = default;
};

// The module's file name and its entry point: extern "C" PetscBackend* <entry>().
inline constexpr const char* petsc_module_file = "libmagfem_petsc.so";
inline constexpr const char* petsc_module_entry = "magfem_petsc_backend";

// The backend, opening the module on the first call of the process (thread-safe). Throws
// BackendModuleError (core/backend_module.hpp) when the module cannot be loaded.
PetscBackend& petsc_backend();
// The backend if the module has been opened, else null; never opens it (error paths and the
// collective helpers of a serial run must not pay for PETSc).
PetscBackend* loaded_petsc_backend();

} // namespace magfem
