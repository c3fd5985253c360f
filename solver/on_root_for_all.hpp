#pragma once
// Inside the PETSc module: work that process 0 does alone for every process (the mesh's
// partition, pmg_partition.cpp), its outcome told to all before anything else is sent. Should
// it throw, every process throws alike instead of waiting for a result that never comes (a
// hang under mpirun, and no exit code): process 0 with its own message, the others naming
// what failed and where.
#include <exception>
#include <string>

#include <mpi.h>

#include "core/input_error.hpp"

namespace magfem::petsc_module {

// Collective over `comm`. Runs `work()` on process 0; throws SolveError on every process if it
// threw, whatever it threw (process 0: its message; the others: "<what> failed on process 0").
template <class Work> void on_root_for_all(MPI_Comm comm, const std::string& what, Work&& work) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string failure;
  if (rank == 0) {
    try {
      work();
    } catch (const std::exception& e) {
      failure = e.what();
    } catch (...) {
      failure = what + " failed on process 0 (an exception that is not a std::exception)";
    }
  }
  int failed = !failure.empty();
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm);
  if (failed)
    throw SolveError(rank == 0 ? failure : what + " failed on process 0");
}

} // namespace magfem::petsc_module
