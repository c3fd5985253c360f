#pragma once
// Inside the PETSc module (petsc_backend.hpp): the MPI side of mpi_context.hpp. The functions
// are those of the same names there; join_mpi_world is called only under mpirun.
#include <sched.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "solver/petsc_backend.hpp"

namespace magfem::petsc_module {

MpiWorld join_mpi_world(bool any_thread_calls_mpi);
MpiWorld started_mpi_world();
bool same_on_every_rank(std::uint64_t value);
void sum_on_every_rank(double* values, std::size_t n);
void union_to_root(float* values, std::size_t n);
void idle_barrier();
void lend_node_cores_to_root();
// Collective: the union of the CPU affinities of the run's processes on this process's machine
// (this process's own affinity in a serial run).
cpu_set_t node_cores();
int code_of_root(int code);
void broadcast_bytes(int root, std::string& bytes);
// MPI_Abort when distributed; returns otherwise (the caller exits).
void abort_mpi_world(int code);

class MpiWorkDealer final : public WorkDealerEngine {
public:
  MpiWorkDealer(std::vector<int> items, int workers);
  ~MpiWorkDealer() override;
  MpiWorkDealer(const MpiWorkDealer&) = delete;
  MpiWorkDealer& operator=(const MpiWorkDealer&) = delete;

  int next(int worker, int finished, const std::string& result) override;
  void serve(const std::function<void(int item, const std::string& result)>& on_result) override;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace magfem::petsc_module
