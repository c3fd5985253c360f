// The entry point of libmagfem_petsc.so (petsc_backend.hpp): the one backend object, whose
// methods forward to the module's PETSc and MPI code.
#include "solver/mpi_world_backend.hpp"
#include "solver/petsc_ksp_solver.hpp"
#include "solver/pmg_partition.hpp"

namespace magfem::petsc_module {
namespace {

class Backend final : public PetscBackend {
public:
  void start_petsc(bool any_thread_calls_mpi) override {
    petsc_module::start_petsc(any_thread_calls_mpi);
  }
  std::unique_ptr<PetscSolverEngine> make_solver(PetscSolverOptions options) override {
    return std::make_unique<PetscKspSolver>(std::move(options));
  }
  std::string petsc_options_problem(const PetscSolverOptions& options) override {
    return petsc_module::petsc_options_problem(options);
  }
  DistributedRows
  partition_distributed_rows(const Eigen::SparseMatrix<double>& vertex_pattern,
                             const Eigen::SparseMatrix<double, Eigen::RowMajor>& prolongation,
                             const std::vector<int>* smoother_block) override {
    return partition_for_pmg(vertex_pattern, prolongation, smoother_block);
  }
  MpiWorld join_mpi_world(bool any_thread_calls_mpi) override {
    return petsc_module::join_mpi_world(any_thread_calls_mpi);
  }
  MpiWorld started_mpi_world() override { return petsc_module::started_mpi_world(); }
  bool same_on_every_rank(std::uint64_t value) override {
    return petsc_module::same_on_every_rank(value);
  }
  void sum_on_every_rank(double* values, std::size_t n) override {
    petsc_module::sum_on_every_rank(values, n);
  }
  void union_to_root(float* values, std::size_t n) override {
    petsc_module::union_to_root(values, n);
  }
  void idle_barrier() override { petsc_module::idle_barrier(); }
  void lend_node_cores_to_root() override { petsc_module::lend_node_cores_to_root(); }
  int code_of_root(int code) override { return petsc_module::code_of_root(code); }
  void broadcast_bytes(int root, std::string& bytes) override {
    petsc_module::broadcast_bytes(root, bytes);
  }
  std::unique_ptr<WorkDealerEngine> make_work_dealer(std::vector<int> items, int workers) override {
    return std::make_unique<MpiWorkDealer>(std::move(items), workers);
  }
  void abort_mpi_world(int code) override { petsc_module::abort_mpi_world(code); }
};

} // namespace
} // namespace magfem::petsc_module

// The one symbol the module exports (the rest is hidden: CMake's visibility preset).
extern "C" __attribute__((visibility("default"))) void* magfem_petsc_backend() {
  static magfem::petsc_module::Backend backend;
  return static_cast<magfem::PetscBackend*>(&backend);
}
