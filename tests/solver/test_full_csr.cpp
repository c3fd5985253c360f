// The full CSR of a symmetric matrix from its lower triangle (solver/full_csr.hpp), which PETSc
// and pmg's smoother read: against Eigen's own symmetric expansion, on 1, 2 and 3 threads.
#include <gtest/gtest.h>

#include <random>

#include <Eigen/SparseCore>

#include "core/input_error.hpp"
#include "solver/full_csr.hpp"

namespace magfem {
namespace {

// A random symmetric pattern's lower triangle, n x n, with every diagonal entry and some
// columns empty below it (rows that get no left part, columns no right part but the diagonal).
Eigen::SparseMatrix<double> random_lower(int n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::uniform_int_distribution<int> row(0, n - 1);
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < n; ++j) {
    entries.emplace_back(j, j, 10 + uniform(random));
    for (int k = 0; k < (j % 7 == 0 ? 0 : 6); ++k) {
      const int i = row(random);
      if (i > j)
        entries.emplace_back(i, j, uniform(random));
    }
  }
  Eigen::SparseMatrix<double> lower(n, n);
  lower.setFromTriplets(entries.begin(), entries.end());
  return lower;
}

void expect_full_csr(const Eigen::SparseMatrix<double>& lower, int threads) {
  const Eigen::SparseMatrix<double, Eigen::RowMajor> expected =
      lower.selfadjointView<Eigen::Lower>();
  const FullCsr full = full_csr_from_lower(lower, threads);
  const int n = static_cast<int>(lower.rows());
  ASSERT_EQ(full.row_start.size(), static_cast<std::size_t>(n) + 1);
  ASSERT_EQ(full.row_start.back(), expected.nonZeros());
  for (int i = 0; i < n; ++i) {
    ASSERT_EQ(full.row_start[i], expected.outerIndexPtr()[i]) << "row " << i;
    for (int k = full.row_start[i]; k < full.row_start[i + 1]; ++k) {
      EXPECT_EQ(full.column[k], expected.innerIndexPtr()[k]) << "row " << i;
      EXPECT_EQ(full.value[k], expected.valuePtr()[k]) << "row " << i;
    }
  }
}

} // namespace

// Row i is column i's entries (on and below the diagonal) after the lower entries of row i,
// columns sorted, values the same bits: Eigen's selfadjointView makes the same matrix. On
// several threads each thread's range of columns places its entries after the ranges before
// it. Planted and caught: the ranges' offsets summed in reverse (rows with unsorted columns),
// a row's right part started one entry early, the last range's columns left out.
TEST(FullCsr, IsTheSymmetricExpansionOfTheLowerTriangleOnAnyThreadCount) {
  for (int n : {1, 40, 3001}) {
    const Eigen::SparseMatrix<double> lower = random_lower(n, 5u + n);
    for (int threads : {1, 2, 3}) {
      SCOPED_TRACE("n " + std::to_string(n) + ", threads " + std::to_string(threads));
      expect_full_csr(lower, threads);
    }
  }
}

// An uncompressed lower triangle (Eigen's insert()) gives the same CSR as its compressed copy.
TEST(FullCsr, UncompressedInputIsReadAsItsCompressedCopy) {
  Eigen::SparseMatrix<double> lower = random_lower(200, 3);
  Eigen::SparseMatrix<double> uncompressed(200, 200);
  uncompressed.reserve(Eigen::VectorXi::Constant(200, 12));
  for (int j = 0; j < lower.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it)
      uncompressed.insert(it.row(), it.col()) = it.value();
  ASSERT_FALSE(uncompressed.isCompressed());
  expect_full_csr(uncompressed, 2);
}

// A compressed matrix whose columns hold their rows out of order (Eigen does not require the
// order) still gives rows with sorted columns, as PETSc requires: the branch that sorts them.
// Planted and caught: that branch skipped (row 3's columns come out 2, 0).
TEST(FullCsr, RowsComeOutSortedFromColumnsOutOfOrder) {
  // Lower triangle of a 4 x 4 matrix, CSC with column 0's rows as 0, 3, 1 (out of order).
  const std::vector<int> outer{0, 3, 5, 7, 8};
  const std::vector<int> inner{0, 3, 1, 1, 2, 2, 3, 3};
  const std::vector<double> values{4, -1, -2, 5, -3, 6, -4, 7};
  const Eigen::Map<const Eigen::SparseMatrix<double>> mapped(4, 4, 8, outer.data(), inner.data(),
                                                             values.data());
  const Eigen::SparseMatrix<double> lower = mapped;
  ASSERT_EQ(lower.innerIndexPtr()[1], 3) << "the copy must keep the out-of-order rows";
  const FullCsr full = full_csr_from_lower(lower, 2);
  const std::vector<int> row_start{0, 3, 6, 9, 12};
  const std::vector<int> column{0, 1, 3, 0, 1, 2, 1, 2, 3, 0, 2, 3};
  const std::vector<double> value{4, -2, -1, -2, 5, -3, -3, 6, -4, -1, -4, 7};
  EXPECT_EQ(full.row_start, row_start);
  EXPECT_EQ(std::vector<int>(full.column.begin(), full.column.end()), column);
  EXPECT_EQ(std::vector<double>(full.value.begin(), full.value.end()), value);
}

// An entry above the diagonal is an internal error, not silently mirrored.
TEST(FullCsr, AnEntryAboveTheDiagonalIsRefused) {
  Eigen::SparseMatrix<double> a(3, 3);
  a.insert(0, 0) = 1;
  a.insert(0, 2) = 0.5;
  a.insert(2, 2) = 1;
  a.makeCompressed();
  EXPECT_THROW(full_csr_from_lower(a, 2), SolveError);
}

} // namespace magfem
