#pragma once
// The processes of one run when magfem is launched by mpirun: which one this is, how many
// there are, and the few collective operations the distributed 3D solve needs outside the
// linear algebra (agreeing that replicated data is identical, stopping every process on an
// error). MPI itself stays in mpi_context.cpp and petsc_solver.cpp; nothing else includes it.
//
// A process not launched by mpirun never starts MPI here (a serial run pays nothing).
#include <cstdint>
#include <string>

namespace magfem {

struct MpiWorld {
  int rank = 0;         // this process in MPI_COMM_WORLD
  int size = 1;         // processes in MPI_COMM_WORLD; 1 = a serial run
  int size_on_node = 1; // of them on this machine (they share its memory)
  bool distributed() const { return size > 1; }
  bool is_root() const { return rank == 0; }
};

// True when the environment says this process was started by mpirun (Open MPI's
// OMPI_COMM_WORLD_SIZE, MPICH/Hydra's PMI_SIZE), whatever the number of processes.
bool launched_by_mpirun();

// Under mpirun: starts MPI (through PETSc, which the distributed solve needs anyway) and
// returns this process's place in MPI_COMM_WORLD. Otherwise {0, 1, 1}, and MPI stays off.
MpiWorld join_mpi_world();

// This process's place in MPI_COMM_WORLD if MPI has been started (and not yet stopped),
// else {0, 1, 1}; never starts it. For error paths, which must not start MPI.
MpiWorld started_mpi_world();

// Collective: whether every process passed the same value (e.g. a hash of a replicated mesh).
bool same_on_every_rank(std::uint64_t value);

// Collective: waits until every process has arrived, sleeping between checks. Open MPI's
// blocking calls spin on the CPU; processes waiting here for rank 0's post-processing leave
// it the cores instead.
void idle_barrier();

// Ends every process of the run with `code` (MPI_Abort): an error on one process must not
// leave the others waiting in a collective call for ever.
[[noreturn]] void abort_mpi_world(int code);

} // namespace magfem
