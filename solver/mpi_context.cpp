#include "solver/mpi_context.hpp"

#include <mpi.h>

#include <chrono>
#include <cstdlib>
#include <thread>

#include "solver/petsc_solver.hpp"

namespace magfem {

bool launched_by_mpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr;
}

MpiWorld started_mpi_world() {
  MpiWorld world;
  int started = 0, finalized = 0;
  MPI_Initialized(&started);
  MPI_Finalized(&finalized);
  if (!started || finalized)
    return world;
  MPI_Comm_rank(MPI_COMM_WORLD, &world.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &world.size);
  return world;
}

MpiWorld join_mpi_world() {
  MpiWorld world;
  if (!launched_by_mpirun())
    return world;
  start_petsc(); // MPI_Init, and PETSc's error handling, once for the process
  MPI_Comm_rank(MPI_COMM_WORLD, &world.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &world.size);
  MPI_Comm node = MPI_COMM_NULL;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, world.rank, MPI_INFO_NULL, &node);
  if (node != MPI_COMM_NULL) {
    MPI_Comm_size(node, &world.size_on_node);
    MPI_Comm_free(&node);
  }
  return world;
}

bool same_on_every_rank(std::uint64_t value) {
  if (!started_mpi_world().distributed())
    return true;
  std::uint64_t low = value, high = value;
  MPI_Allreduce(MPI_IN_PLACE, &low, 1, MPI_UINT64_T, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &high, 1, MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD);
  return low == high;
}

void idle_barrier() {
  if (!started_mpi_world().distributed())
    return;
  MPI_Request request = MPI_REQUEST_NULL;
  MPI_Ibarrier(MPI_COMM_WORLD, &request);
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done)
      return;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

void abort_mpi_world(int code) {
  if (started_mpi_world().distributed())
    MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

} // namespace magfem
