#pragma once
// Inside the PETSc module: the distributed MPIAIJ matrix of own-row assembly
// (distributed_rows.hpp). Each process gives the lower triangle it assembled from the
// tetrahedra touching its rows; the full rows it owns are complete in it, and only those go
// into the matrix, as PETSc's two blocks of them read in place (no copy, no entry inserted one
// by one): no entry goes to another process (no stash, no message at assembly), and the
// entries of its ghost tetrahedra outside its rows are left out.
#include <petscmat.h>

#include <Eigen/SparseCore>

#include "solver/pmg_partition.hpp"

namespace magfem::petsc_module {

// Collective over PETSC_COMM_WORLD. `lower`: this process's lower triangle (the whole
// system's size, in equations); `rows`: the same partition on every process. The caller
// destroys the matrix. Throws SolveError if PETSc fails.
Mat own_row_matrix(const Eigen::SparseMatrix<double>& lower, const PmgPartition& rows);

} // namespace magfem::petsc_module
