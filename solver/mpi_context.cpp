#include "solver/mpi_context.hpp"

#include <algorithm>
#include <cstdlib>
#include <thread>

#include "solver/petsc_backend.hpp"

// MPI is called from the PETSc module (petsc_backend.hpp). A serial run never opens it: the
// collective helpers below are then trivial, and error paths only ask whether it is open.
namespace magfem {

bool launched_by_mpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr;
}

MpiWorld started_mpi_world() {
  PetscBackend* backend = loaded_petsc_backend();
  return backend ? backend->started_mpi_world() : MpiWorld{};
}

MpiWorld join_mpi_world(bool any_thread_calls_mpi) {
  if (!launched_by_mpirun())
    return MpiWorld{};
  return petsc_backend().join_mpi_world(any_thread_calls_mpi);
}

int threads_per_process(const MpiWorld& world) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, cores / std::max(1, world.size_on_node));
}

bool same_on_every_rank(std::uint64_t value) {
  PetscBackend* backend = loaded_petsc_backend();
  return backend ? backend->same_on_every_rank(value) : true;
}

void sum_on_every_rank(double* values, std::size_t n) {
  if (PetscBackend* backend = loaded_petsc_backend())
    backend->sum_on_every_rank(values, n);
}

void union_to_root(float* values, std::size_t n) {
  if (PetscBackend* backend = loaded_petsc_backend())
    backend->union_to_root(values, n);
}

void idle_barrier() {
  if (PetscBackend* backend = loaded_petsc_backend())
    backend->idle_barrier();
}

void lend_node_cores_to_root() {
  if (PetscBackend* backend = loaded_petsc_backend())
    backend->lend_node_cores_to_root();
}

int code_of_root(int code) {
  PetscBackend* backend = loaded_petsc_backend();
  return backend ? backend->code_of_root(code) : code;
}

void broadcast_bytes(int root, std::string& bytes) {
  if (PetscBackend* backend = loaded_petsc_backend())
    backend->broadcast_bytes(root, bytes);
}

WorkDealer::WorkDealer(std::vector<int> items, int workers)
    : engine_(petsc_backend().make_work_dealer(std::move(items), workers)) {}

WorkDealer::~WorkDealer() = default;

int WorkDealer::next(int worker, int finished, const std::string& result) {
  return engine_->next(worker, finished, result);
}

void WorkDealer::serve(const std::function<void(int item, const std::string& result)>& on_result) {
  engine_->serve(on_result);
}

void abort_mpi_world(int code) {
  if (PetscBackend* backend = loaded_petsc_backend())
    backend->abort_mpi_world(code);
  std::exit(code);
}

} // namespace magfem
