#pragma once
// Inside the PETSc module: the distributed p-multigrid's coarse operator P^T A P over
// MPI_COMM_WORLD (petsc_ksp_solver.cpp). Each process forms the share of its own fine rows
// (partial_galerkin_product, galerkin_product.hpp) from the rows of `a` it holds, on one
// thread; sends every coarse row of that share to the process that owns it; and adds the
// shares it receives row by row, in process order, so that every run gives the same bits.
//
// Why not PETSc's MatPtAP: the same general triple product that serially took five times our
// row-wise one (galerkin_product.hpp), here on each process beside the smoother's factor.
#include <petscmat.h>

#include <Eigen/SparseCore>

#include "solver/pmg_partition.hpp"

namespace magfem::petsc_module {

// Collective. `a`: the fine matrix (MPIAIJ, or SeqAIJ on one process), its rows those of
// `rows`; `q`: the interpolation from the P1 unknowns, by equation (the whole of it, on every
// process); this process owns coarse rows [coarse_begin, coarse_end) of the numbering
// rows.coarse_order. Returns the coarse operator as an MPIAIJ matrix with those rows; throws
// SolveError if PETSc fails.
Mat distributed_galerkin_product(Mat a, const Eigen::SparseMatrix<double, Eigen::RowMajor>& q,
                                 const PmgPartition& rows, PetscInt coarse_begin,
                                 PetscInt coarse_end);

} // namespace magfem::petsc_module
