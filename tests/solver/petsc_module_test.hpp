#pragma once
// What the tests of the PETSc module's distributed parts share (test_distributed_galerkin_product,
// test_smoother_sweeps). Included by one source of a test executable only: it defines the
// module's check().
#include <stdexcept>
#include <string>

#include <petscsys.h>

namespace magfem::petsc_module {

// The module defines this beside its PETSc error handler (petsc_ksp_solver.cpp); here a
// failing call only needs to fail the test.
void check(PetscErrorCode code, const char* what) {
  if (code != 0)
    throw std::runtime_error(std::string("PETSc: ") + what + " failed");
}

// A child test's start under mpirun: PETSc (and MPI) started, this process's place.
struct ChildWorld {
  int size = 1, rank = 0;
};

inline ChildWorld start_petsc_child() {
  if (PetscInitializeNoArguments() != 0)
    throw std::runtime_error("PetscInitialize failed");
  ChildWorld w;
  MPI_Comm_size(PETSC_COMM_WORLD, &w.size);
  MPI_Comm_rank(PETSC_COMM_WORLD, &w.rank);
  return w;
}

// Item k's process: uneven parts, interleaved (process 0 gets the most), as a mesh partition
// gives a process rows all over the numbering.
inline int interleaved_process(int k, int size) {
  const int h = (k * 37 + 5) % 11;
  return h < 5 ? 0 : h % size;
}

} // namespace magfem::petsc_module
