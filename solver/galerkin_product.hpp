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

} // namespace magfem
