#pragma once
// The Galerkin coarse operator A_c = P^T A P of the two-level p-multigrid (p1_coarse_space.hpp),
// formed row by row on all cores. PETSc's general sparse triple product took 4.9 s of the
// 32-magnet benchmark's 14 s preconditioner set-up (2.1 M fine, 253k coarse unknowns); here
// every fine row of P has one or two entries, so row I of A_c only gathers the fine rows that
// P's column I touches. Each row is summed alone in a fixed order: the same bits whatever the
// thread count.
#include <cstddef>
#include <vector>

#include <Eigen/SparseCore>

namespace magfem {

struct CsrMatrix {
  int rows = 0;
  int cols = 0;
  std::vector<int> row_start; // rows + 1
  std::vector<int> column;    // sorted within each row
  std::vector<double> value;
};

// Coarse rows per block of work (a thread's unit; the result does not depend on it).
inline constexpr std::size_t galerkin_block_rows = 2048;

// A: the whole (both triangles) n x n matrix in CSR, n = p.rows(). P: n x m, compressed.
// threads: 0 = all cores. block_rows > 0 (a parameter so that tests can cut small problems
// into many blocks). Returns P^T A P (m x m) with sorted columns.
CsrMatrix galerkin_product(const int* a_row_start, const int* a_column, const double* a_value,
                           const Eigen::SparseMatrix<double, Eigen::RowMajor>& p, int threads = 0,
                           std::size_t block_rows = galerkin_block_rows);

// One block of the rows a process owns of a distributed A (PETSc keeps them as a diagonal and
// an off-diagonal block): CSR over those rows, `column_equation[c]` the row of P that column c
// stands for.
struct CsrRowBlock {
  const int* row_start = nullptr;
  const int* column = nullptr;
  const double* value = nullptr;
  const int* column_equation = nullptr;
};

// A process's share of P^T A P: sum over its rows r of P(r, :)^T A(r, :) P, where
// `row_equation[r]` is the row of P of its row r (r < n_rows) and A's row r is the sum of the
// blocks' rows r. Rows are the coarse unknowns those rows of P touch (ascending, into
// `coarse_rows`), columns P's (m), sorted. Summed over the processes' shares (in any fixed
// order) it is P^T A P; each entry adds in a fixed order, so the same bits every run.
CsrMatrix partial_galerkin_product(int n_rows, const std::vector<CsrRowBlock>& blocks,
                                   const int* row_equation,
                                   const Eigen::SparseMatrix<double, Eigen::RowMajor>& p,
                                   std::vector<int>& coarse_rows);

} // namespace magfem
