#include "solver/own_row_matrix.hpp"

#include <algorithm>
#include <memory>
#include <numeric>
#include <tuple>
#include <utility>
#include <vector>

#include "solver/petsc_check.hpp"

namespace magfem::petsc_module {

namespace {

// One part of the process's rows (PETSc's "diagonal" block, its own columns numbered from 0,
// or the "off-diagonal" one, other processes' columns by their global number) in CSR.
struct CsrPart {
  std::vector<PetscInt> start, column;
  std::vector<PetscScalar> value;
};

// Both parts, kept alive by the matrix, which reads them in place (attached below).
struct SplitRows {
  CsrPart diagonal, off;
};

PetscErrorCode destroy_split_rows(void* rows) {
  delete static_cast<SplitRows*>(rows);
  return 0;
}

// Columns ascending within each row, as PETSc's CSR has them (a row's columns are distinct:
// the diagonal comes once).
void sort_rows(CsrPart& part) {
  std::vector<std::pair<PetscInt, PetscScalar>> row;
  for (std::size_t r = 0; r + 1 < part.start.size(); ++r) {
    row.clear();
    for (PetscInt k = part.start[r]; k < part.start[r + 1]; ++k)
      row.emplace_back(part.column[k], part.value[k]);
    std::sort(row.begin(), row.end());
    for (std::size_t k = 0; k < row.size(); ++k)
      std::tie(part.column[part.start[r] + k], part.value[part.start[r] + k]) = row[k];
  }
}

} // namespace

Mat own_row_matrix(const Eigen::SparseMatrix<double>& lower, const PmgPartition& rows) {
  const PetscInt begin = rows.own_begin, end = rows.own_end, local = end - begin;
  const auto n = static_cast<PetscInt>(lower.rows());
  // Row r of the symmetric matrix is (r, c <= r) from column c of the lower triangle and
  // (r, c > r) from column r: a lower entry (i, j) belongs to row i and, off the diagonal,
  // to row j. Counted first, then filled in CSR with the distributed column numbers, split
  // as PETSc keeps the rows: columns this process owns (the diagonal block) and the others.
  // Entries exactly zero (P2 vertex pairs whose element couplings cancel) are left out, as the
  // assembly by shares did: kept, BoomerAMG's coarse hierarchy differs and the sphere of
  // tests/cli/test_mpi_solve.cpp took 24 / 25 CG iterations on 2 / 3 processes, against
  // 23 / 24 without them.
  auto split = std::make_unique<SplitRows>();
  CsrPart& diagonal = split->diagonal;
  CsrPart& off = split->off;
  diagonal.start.assign(local + 1, 0);
  off.start.assign(local + 1, 0);
  const auto own = [&](Eigen::Index equation) -> PetscInt {
    const PetscInt r = rows.order[static_cast<std::size_t>(equation)];
    return r >= begin && r < end ? r - begin : -1;
  };
  const auto part_of = [&](PetscInt column) -> CsrPart& {
    return column >= begin && column < end ? diagonal : off;
  };
  for (Eigen::Index j = 0; j < lower.outerSize(); ++j) {
    const PetscInt rj = own(j), cj = rows.order[static_cast<std::size_t>(j)];
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it) {
      if (it.value() == 0)
        continue;
      if (const PetscInt ri = own(it.row()); ri >= 0)
        ++part_of(cj).start[ri + 1];
      if (rj >= 0 && it.row() != j)
        ++part_of(rows.order[static_cast<std::size_t>(it.row())]).start[rj + 1];
    }
  }
  for (CsrPart* part : {&diagonal, &off}) {
    std::partial_sum(part->start.begin(), part->start.end(), part->start.begin());
    part->column.resize(part->start[local]);
    part->value.resize(part->start[local]);
  }
  std::vector<PetscInt> diagonal_fill(diagonal.start.begin(), diagonal.start.end() - 1),
      off_fill(off.start.begin(), off.start.end() - 1);
  const auto put = [&](PetscInt row, PetscInt column, double value) {
    if (column >= begin && column < end) {
      diagonal.column[diagonal_fill[row]] = column - begin;
      diagonal.value[diagonal_fill[row]++] = value;
    } else {
      off.column[off_fill[row]] = column;
      off.value[off_fill[row]++] = value;
    }
  };
  for (Eigen::Index j = 0; j < lower.outerSize(); ++j) {
    const PetscInt rj = own(j), cj = rows.order[static_cast<std::size_t>(j)];
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it) {
      if (it.value() == 0)
        continue;
      if (const PetscInt ri = own(it.row()); ri >= 0)
        put(ri, cj, it.value());
      if (rj >= 0 && it.row() != j)
        put(rj, rows.order[static_cast<std::size_t>(it.row())], it.value());
    }
  }
  sort_rows(diagonal);
  sort_rows(off);
  // PETSc reads the parts in place (the copy and row-by-row insertion of
  // MatCreateMPIAIJWithArrays took 1.7 s of benchmark32's set-up on 2 processes); the
  // container frees them with the matrix. Should a step fail, the matrix goes first (it reads
  // the parts), then the container with the parts once it has them, else `split` does.
  Mat a = nullptr;
  PetscContainer keeper = nullptr;
  try {
    check(MatCreateMPIAIJWithSplitArrays(
              PETSC_COMM_WORLD, local, local, n, n, diagonal.start.data(), diagonal.column.data(),
              diagonal.value.data(), off.start.data(), off.column.data(), off.value.data(), &a),
          "MatCreateMPIAIJWithSplitArrays");
    check(PetscContainerCreate(PETSC_COMM_SELF, &keeper), "PetscContainerCreate");
    check(PetscContainerSetUserDestroy(keeper, destroy_split_rows), "PetscContainerSetUserDestroy");
    check(PetscContainerSetPointer(keeper, split.get()), "PetscContainerSetPointer");
    split.release(); // the container's now
    check(PetscObjectCompose(reinterpret_cast<PetscObject>(a), "magfem_own_rows",
                             reinterpret_cast<PetscObject>(keeper)),
          "PetscObjectCompose");
  } catch (...) {
    MatDestroy(&a);
    PetscContainerDestroy(&keeper);
    throw;
  }
  PetscContainerDestroy(&keeper); // the matrix holds it
  return a;
}

} // namespace magfem::petsc_module
