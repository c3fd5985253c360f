#pragma once
// Inside the PETSc module: y = A x for a square CSR matrix (CsrView) on several threads, rows
// cut into fixed blocks. Each y[i] is one thread's sum over row i in column order, so the
// result does not depend on the thread count or schedule.
#include <cstddef>

#include "core/parallel_blocks.hpp"
#include "solver/block_smoother.hpp"

namespace magfem::petsc_module {

inline void csr_multiply(const CsrView& a, const PetscScalar* x, PetscScalar* y, int threads) {
  // Blocks of rows: a few hundred at benchmark32's 2 M rows, so the last ones balance the
  // threads' shares.
  constexpr std::size_t rows_per_block = 8192;
  parallel_blocks(static_cast<std::size_t>(a.rows), rows_per_block, threads,
                  [&](std::size_t, std::size_t lo, std::size_t hi) {
                    for (std::size_t i = lo; i < hi; ++i) {
                      double sum = 0;
                      for (PetscInt k = a.row_start[i]; k < a.row_start[i + 1]; ++k)
                        sum += a.value[k] * x[a.column[k]];
                      y[i] = sum;
                    }
                  });
}

} // namespace magfem::petsc_module
