#include "solver/own_row_matrix.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>
#include <utility>
#include <vector>

#include "solver/petsc_check.hpp"

namespace magfem::petsc_module {

Mat own_row_matrix(const Eigen::SparseMatrix<double>& lower, const PmgPartition& rows) {
  const PetscInt begin = rows.own_begin, end = rows.own_end, local = end - begin;
  const auto n = static_cast<PetscInt>(lower.rows());
  // Row r of the symmetric matrix is (r, c <= r) from column c of the lower triangle and
  // (r, c > r) from column r: a lower entry (i, j) belongs to row i and, off the diagonal,
  // to row j. Counted first, then filled in CSR with the distributed column numbers. Entries
  // exactly zero (P2 vertex pairs whose element couplings cancel) are left out, as the
  // assembly by shares did: kept, BoomerAMG's coarse hierarchy differs and the sphere of
  // tests/cli/test_mpi_solve.cpp took 24 / 25 CG iterations on 2 / 3 processes, against
  // 23 / 24 without them.
  std::vector<PetscInt> start(local + 1, 0);
  const auto own = [&](Eigen::Index equation) -> PetscInt {
    const PetscInt r = rows.order[static_cast<std::size_t>(equation)];
    return r >= begin && r < end ? r - begin : -1;
  };
  for (Eigen::Index j = 0; j < lower.outerSize(); ++j) {
    const PetscInt rj = own(j);
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it) {
      if (it.value() == 0)
        continue;
      if (const PetscInt ri = own(it.row()); ri >= 0)
        ++start[ri + 1];
      if (rj >= 0 && it.row() != j)
        ++start[rj + 1];
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<PetscInt> column(start[local]), fill(start.begin(), start.end() - 1);
  std::vector<PetscScalar> value(start[local]);
  for (Eigen::Index j = 0; j < lower.outerSize(); ++j) {
    const PetscInt rj = own(j), cj = rows.order[static_cast<std::size_t>(j)];
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it) {
      if (it.value() == 0)
        continue;
      if (const PetscInt ri = own(it.row()); ri >= 0) {
        column[fill[ri]] = cj;
        value[fill[ri]++] = it.value();
      }
      if (rj >= 0 && it.row() != j) {
        column[fill[rj]] = rows.order[static_cast<std::size_t>(it.row())];
        value[fill[rj]++] = it.value();
      }
    }
  }
  // Columns ascending within each row, as a CSR matrix for PETSc has them (a row's columns are
  // distinct: the diagonal comes once).
  std::vector<std::pair<PetscInt, PetscScalar>> row;
  for (PetscInt r = 0; r < local; ++r) {
    row.clear();
    for (PetscInt k = start[r]; k < start[r + 1]; ++k)
      row.emplace_back(column[k], value[k]);
    std::sort(row.begin(), row.end());
    for (std::size_t k = 0; k < row.size(); ++k)
      std::tie(column[start[r] + k], value[start[r] + k]) = row[k];
  }
  Mat a = nullptr;
  // Copies the arrays, preallocates from them exactly and sets each own row once.
  check(MatCreateMPIAIJWithArrays(PETSC_COMM_WORLD, local, local, n, n, start.data(), column.data(),
                                  value.data(), &a),
        "MatCreateMPIAIJWithArrays");
  return a;
}

} // namespace magfem::petsc_module
