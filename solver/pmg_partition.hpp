#pragma once
// Inside the PETSc module: which rows of a distributed p-multigrid system (PCMG over
// MPI_COMM_WORLD, petsc_ksp_solver.cpp) each process owns. The DOF numbering puts the vertices
// first and the edge midpoints after, by vertex pair, so contiguous blocks of it cut through the
// whole mesh, and block Jacobi across the processes then drops most couplings (magnetized
// sphere at --mesh-scale 2.5, 2 processes: 81 CG iterations against 19 serially). Instead
// the mesh is partitioned: the P1 graph (vertex equations, coupled where a tetrahedron joins
// them) by Scotch (PETSc's MatPartitioning) on process 0, one part per process, the same in
// every run (fixed seed, one thread), each vertex weighted by
// the equations that go with it (itself and the edge midpoints whose first free end it is).
// The open-boundary shell (the smoother block) goes whole to process 0, which solves it by
// one Cholesky factor as the serial smoother does: cut between processes, block Jacobi drops
// the shell's strong tangential couplings at the cut (40 iterations on the sphere against 21
// with the shell whole); process 0 takes correspondingly less of the rest (part weights).
// Each process's rows follow the previous process's, in equation order within (the serial
// Gauss-Seidel order); the P1 unknowns likewise by their vertex's part. The same on every
// process (process 0's parts are sent to all).
#include <vector>

#include <petscmat.h>

#include <type_traits>

#include <Eigen/SparseCore>

#include "solver/distributed_rows.hpp"

namespace magfem::petsc_module {

// The rows outside the module too (own-row assembly before the matrix exists): PETSc's
// index type is int here (Debian's PETSc: 32-bit).
static_assert(std::is_same_v<PetscInt, int>);
using PmgPartition = DistributedRows;

// Collective over PETSC_COMM_WORLD. `lower_pattern`: the whole system's lower triangle
// (values unused; only the couplings of vertex equations are read, so the P1 graph of
// vertex_coupling_pattern serves as well), `q`: the interpolation from the P1 unknowns
// (p1_coarse_space.hpp), `smoother_block`: the shell's equations (or null); all the same on every
// process. Throws SolveError if PETSc fails.
PmgPartition partition_for_pmg(const Eigen::SparseMatrix<double>& lower_pattern,
                               const Eigen::SparseMatrix<double, Eigen::RowMajor>& q,
                               const std::vector<int>* smoother_block);

} // namespace magfem::petsc_module
