// pmg's fine-level smoother with a block (solver/block_smoother.hpp), on its own: a 7-point
// Laplacian on a 6 x 5 x 5 grid whose first layer (x = 0) is the block, so that the point
// equations fall into both groups: the next layer is coupled to the block ("near"), the other
// four are not ("far"). The smoother is x <- x + M^-1 (b - A x); each test reads M^-1 column by
// column from the smoother itself (a unit residual r = e_k: b = A x + r from a random x) and
// compares it with a dense reference.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include <Eigen/Dense>

#include "solver/block_smoother.hpp"

namespace magfem::petsc_module {
namespace {

constexpr int nx = 6, ny = 5, nz = 5, n = nx * ny * nz;

int index_of(int i, int j, int k) {
  return i + nx * (j + ny * k);
}

// The Laplacian with a diagonal shift (SPD: strictly diagonally dominant) in CSR with sorted
// columns, as the smoother reads it.
struct Grid {
  std::vector<PetscInt> row_start{0}, column;
  std::vector<PetscScalar> value;
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  std::vector<int> block; // the layer x = 0
  Grid() {
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          const int row = index_of(i, j, k);
          dense(row, row) = 6.5;
          if (i > 0)
            dense(row, index_of(i - 1, j, k)) = -1;
          if (i + 1 < nx)
            dense(row, index_of(i + 1, j, k)) = -1;
          if (j > 0)
            dense(row, index_of(i, j - 1, k)) = -1;
          if (j + 1 < ny)
            dense(row, index_of(i, j + 1, k)) = -1;
          if (k > 0)
            dense(row, index_of(i, j, k - 1)) = -1;
          if (k + 1 < nz)
            dense(row, index_of(i, j, k + 1)) = -1;
          if (i == 0)
            block.push_back(row);
        }
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c)
        if (dense(r, c) != 0) {
          column.push_back(c);
          value.push_back(dense(r, c));
        }
      row_start.push_back(static_cast<PetscInt>(column.size()));
    }
  }
  CsrView view() const { return {n, row_start.data(), column.data(), value.data()}; }
};

// M^-1 of one smoothing step (down or up), column k from the residual e_k, starting from a
// random x (or from zero with the zero-guess path): for a fixed splitting the start does not
// matter.
Eigen::MatrixXd inverse_of_splitting(const Grid& g, BlockSmoother& s, bool down, bool zero_guess,
                                     int threads) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Eigen::MatrixXd inverse(n, n);
  for (int k = 0; k < n; ++k) {
    Eigen::VectorXd x0 = Eigen::VectorXd::Zero(n);
    if (!zero_guess)
      for (int i = 0; i < n; ++i)
        x0[i] = uniform(random);
    Eigen::VectorXd b = g.dense * x0;
    b[k] += 1;
    Eigen::VectorXd x = x0;
    s.smooth(b.data(), x.data(), down, zero_guess, 1, threads);
    inverse.col(k) = x - x0;
  }
  return inverse;
}

// The smoother's M for Gauss-Seidel in the order block, far, near with the block's equations
// solved together: A's entries on and below the diagonal in that order, the block's whole
// diagonal block. Far: the point equations not coupled to the block.
Eigen::MatrixXd block_gauss_seidel(const Grid& g) {
  std::vector<int> position(n);
  std::vector<int> group(n, 2); // 0 block, 1 far, 2 near
  for (int e : g.block)
    group[e] = 0;
  for (int r = 0; r < n; ++r)
    if (group[r] != 0) {
      bool near = false;
      for (int e : g.block)
        near = near || g.dense(r, e) != 0;
      group[r] = near ? 2 : 1;
    }
  int next = 0;
  for (int want = 0; want < 3; ++want)
    for (int r = 0; r < n; ++r)
      if (group[r] == want)
        position[r] = next++;
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      if (position[c] <= position[r] || (group[r] == 0 && group[c] == 0))
        m(r, c) = g.dense(r, c);
  return m;
}

double relative_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).norm() / b.norm();
}

} // namespace

// Down is block Gauss-Seidel in the order block, far, near (the block's solve and the far
// sweep touch disjoint unknowns, which is what lets them run side by side), and up is its
// transpose, so the V-cycle stays symmetric for CG. 1e-12: CHOLMOD's solve of a 25-equation
// block and a 150 x 150 dense inverse agree to about 1e-15. Planted and caught: the near
// equations swept with the far ones (they then read the block's values from before its solve:
// block Jacobi between the two, 0.12 off), up's near sweep after the block (up no longer the
// transpose: 0.14), the block's residual taken before up's near sweep (0.077). Whether the
// two threads give the bits of one is PmgSetUp's check (MAGFEM_THREADS 1, 2, 3); the far
// sweep reads no block value, so no ordering of the two threads can change a bit here.
TEST(BlockSmoother, DownIsBlockGaussSeidelInTheOrderBlockFarNearAndUpIsItsTranspose) {
  const Grid g;
  BlockFactorCache cache;
  BlockSmoother s(g.view(), g.block, cache);
  const Eigen::MatrixXd expected = block_gauss_seidel(g).inverse();
  for (int threads : {1, 2})
    for (bool zero_guess : {false, true}) {
      SCOPED_TRACE((zero_guess ? "from x = 0, threads " : "from a random x, threads ") +
                   std::to_string(threads));
      const Eigen::MatrixXd down = inverse_of_splitting(g, s, true, zero_guess, threads);
      const Eigen::MatrixXd up = inverse_of_splitting(g, s, false, zero_guess, threads);
      EXPECT_LT(relative_difference(down, expected), 1e-12);
      EXPECT_LT(relative_difference(up, expected.transpose()), 1e-12);
    }
}

// The many-column sweeps (the inductance's block CG) are the same smoother: each column of
// smooth_many equals smooth on that column. Planted and caught: smooth_many keeping the old
// order (the block, then every point equation in index order).
TEST(BlockSmoother, ManyColumnsAreEachColumnsSmoothing) {
  const Grid g;
  BlockFactorCache cache;
  BlockSmoother s(g.view(), g.block, cache);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-1, 1);
  ColumnBlock b(n, 3), x0(n, 3);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      b(i, c) = uniform(random), x0(i, c) = uniform(random);
  for (bool down : {true, false}) {
    ColumnBlock x = x0;
    s.smooth_many(b, x, down, false, 2);
    for (int c = 0; c < 3; ++c) {
      Eigen::VectorXd bc = b.col(c), xc = x0.col(c);
      s.smooth(bc.data(), xc.data(), down, false, 1, 1);
      EXPECT_LT((xc - x.col(c)).norm(), 1e-13 * xc.norm()) << (down ? "down" : "up") << c;
    }
  }
}

} // namespace magfem::petsc_module
