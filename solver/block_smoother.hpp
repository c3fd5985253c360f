#pragma once
// Inside the PETSc module: pmg's fine-level smoother with a block (petsc_ksp_solver.cpp), on a
// matrix in CSR: serially the whole system, distributed a process's diagonal block.
#include <Eigen/CholmodSupport>

#include <algorithm>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <petscsys.h>

#include "core/input_error.hpp"
#include "solver/simultaneous_pcg.hpp"

namespace magfem::petsc_module {

// The fine-level smoother of pmg when some equations form a block (the open-boundary shell):
// block Gauss-Seidel with that block solved exactly (CHOLMOD) and point Gauss-Seidel on every
// other equation. Down (before the coarse correction): the block, then a forward sweep over
// the others; up (after it): a backward sweep, then the block. Up is the transpose of down,
// so the V-cycle stays symmetric, as CG needs. Why a block: in the shell the metric's
// tangential coefficient exceeds the radial one by (r / (R2 - r))^2, which reaches
// (R2 / h)^2 in the outermost layer of elements: anisotropy that grows under refinement and
// that no point smoother (Gauss-Seidel, Jacobi, Chebyshev over either) removes.
//
// The point equations are swept in two groups: `far`, those not coupled to the block, then
// `near`, those that are. Down is then block, far, near and up near, far, block; the block's
// solve and the far sweep read and write disjoint unknowns, so they run at the same time on
// two threads (benchmark32: a 2.9 s block solve beside a 4.0 s sweep in CG's 12 s) and give
// the same bits on one. Still a Gauss-Seidel ordering, so up stays the transpose of down.
//
// Distributed, the rows that read other processes' unknowns form a fourth group, `last`
// (put_last): swept after near going down and before it going up, process after process
// (smoother_sweeps.hpp). Serially it is empty.
//
// The block's factorization outlives the smoother (BlockFactorCache): Newton sets the
// preconditioner up again at every step, but the shell holds air only, so its block is the
// same matrix every time, and its Cholesky factor (most of the set-up: 99 M entries, 9 s at
// 2 M unknowns) is reused as long as the block's entries are bit for bit the ones it was
// computed from. Any change (iron next to the shell, a new mesh) factorizes again.
using BlockFactor = Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower>;
struct BlockFactorCache {
  std::vector<int> outer, inner;       // the block's lower triangle, CSC
  std::vector<double> values;          // ... and its entries
  std::shared_ptr<BlockFactor> factor; // computed from exactly these
  int factorizations = 0;              // how many were computed (not reused)
};

// s -= (row i of the CSR matrix) x, for every column of x at once. Plain loops over a row's
// columns (contiguous in the row-major block) rather than an Eigen expression per entry: this
// is the inner loop of the block solve's smoother and product, and the expression's set-up
// per matrix entry cost as much as the arithmetic.
inline void subtract_row_products(const PetscInt* row_start, const PetscInt* column,
                                  const PetscScalar* value, PetscInt i, const ColumnBlock& x,
                                  double* s) {
  const Eigen::Index m = x.cols();
  const double* xd = x.data();
  for (PetscInt k = row_start[i]; k < row_start[i + 1]; ++k) {
    const double a = value[k];
    const double* xk = xd + static_cast<Eigen::Index>(column[k]) * m;
    for (Eigen::Index c = 0; c < m; ++c)
      s[c] -= a * xk[c];
  }
}

// A square matrix in CSR (sorted columns) whose arrays live elsewhere: serially the whole
// system's (PetscKspSolver's own arrays), distributed the process's diagonal block inside
// PETSc's matrix, read in place rather than copied (issue 33: the copy was 7 % of a process's
// peak memory).
struct CsrView {
  PetscInt rows = 0;
  const PetscInt* row_start = nullptr; // rows + 1
  const PetscInt* column = nullptr;
  const PetscScalar* value = nullptr;
};

// Each equation's place in the block (0, 1, ...) or -1 outside it; `block`: sorted.
inline std::vector<PetscInt> block_places(PetscInt n, const std::vector<int>& block) {
  std::vector<PetscInt> place(n, -1);
  for (int e : block) {
    if (e < 0 || e >= n)
      throw SolveError("internal: a smoother block equation is out of range");
    place[e] = 0;
  }
  PetscInt next = 0;
  for (PetscInt i = 0; i < n; ++i)
    if (place[i] >= 0)
      place[i] = next++;
  return place;
}

// The block's lower triangle (CSC, in the block's numbering) from the whole matrix in CSR.
inline Eigen::SparseMatrix<double> block_lower_triangle(CsrView a,
                                                        const std::vector<PetscInt>& place) {
  std::vector<Eigen::Triplet<double>> entries;
  PetscInt m = 0;
  for (PetscInt i = 0; i < a.rows; ++i) {
    const PetscInt b = place[i];
    if (b < 0)
      continue;
    ++m;
    for (PetscInt k = a.row_start[i]; k < a.row_start[i + 1]; ++k) {
      const PetscInt j = place[a.column[k]];
      if (j >= b)
        entries.emplace_back(static_cast<int>(j), static_cast<int>(b), a.value[k]);
    }
  }
  Eigen::SparseMatrix<double> lower(m, m);
  lower.setFromTriplets(entries.begin(), entries.end());
  lower.makeCompressed();
  return lower;
}

// The same from the whole matrix's lower triangle in CSC (what the assembler hands over), so
// that the block's factorization can start before the full CSR exists.
inline Eigen::SparseMatrix<double> block_lower_triangle(const Eigen::SparseMatrix<double>& lower,
                                                        const std::vector<int>& block) {
  const std::vector<PetscInt> place = block_places(static_cast<PetscInt>(lower.rows()), block);
  std::vector<Eigen::Triplet<double>> entries;
  PetscInt m = 0;
  for (Eigen::Index j = 0; j < lower.outerSize(); ++j) {
    const PetscInt b = place[j];
    if (b < 0)
      continue;
    ++m;
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it) {
      const PetscInt i = place[it.row()];
      if (i >= b)
        entries.emplace_back(static_cast<int>(i), static_cast<int>(b), it.value());
    }
  }
  Eigen::SparseMatrix<double> block_lower(m, m);
  block_lower.setFromTriplets(entries.begin(), entries.end());
  block_lower.makeCompressed();
  return block_lower;
}

// The block's Cholesky factor: the cached one while `lower` is bit for bit the matrix it was
// computed from, else computed (and cached). Null for an empty block.
inline std::shared_ptr<const BlockFactor> factorize_block(const Eigen::SparseMatrix<double>& lower,
                                                          BlockFactorCache& cache) {
  const Eigen::Index m = lower.rows();
  if (m == 0)
    return nullptr;
  const auto same = [](const auto* data, Eigen::Index n, const auto& kept) {
    return static_cast<std::size_t>(n) == kept.size() && std::equal(data, data + n, kept.begin());
  };
  if (!cache.factor || !same(lower.outerIndexPtr(), m + 1, cache.outer) ||
      !same(lower.innerIndexPtr(), lower.nonZeros(), cache.inner) ||
      !same(lower.valuePtr(), lower.nonZeros(), cache.values)) {
    auto factor = std::make_shared<BlockFactor>();
    // Nested dissection: the shell is a thick spherical layer, where METIS's ordering fills
    // in a third of what AMD's does (11 against 35 GFlop at 53k equations).
    factor->cholmod().nmethods = 1;
    factor->cholmod().method[0].ordering = CHOLMOD_METIS;
    factor->compute(lower);
    if (factor->info() != Eigen::Success)
      throw SolveError("the p-multigrid smoother's block is not positive definite");
    cache.outer.assign(lower.outerIndexPtr(), lower.outerIndexPtr() + m + 1);
    cache.inner.assign(lower.innerIndexPtr(), lower.innerIndexPtr() + lower.nonZeros());
    cache.values.assign(lower.valuePtr(), lower.valuePtr() + lower.nonZeros());
    cache.factor = std::move(factor);
    ++cache.factorizations;
  }
  return cache.factor;
}

class BlockSmoother {
public:
  // `a`: the whole symmetric matrix (its arrays must outlive the smoother). `block`: sorted
  // equations. `cache`: the last factorization.
  BlockSmoother(CsrView a, const std::vector<int>& block, BlockFactorCache& cache)
      : BlockSmoother(a, block_places(a.rows, block)) {
    factor_ = factorize_block(block_lower_triangle(a, place_), cache);
  }
  // The same with the block's factor already computed (factorize_block).
  BlockSmoother(CsrView a, const std::vector<int>& block, std::shared_ptr<const BlockFactor> factor)
      : BlockSmoother(a, block_places(a.rows, block)) {
    if (!block_.empty() && !factor)
      throw SolveError("internal: a smoother block without its factor");
    // A factor computed apart (another thread, another copy of the block) must be this one's.
    if (factor && factor->rows() != static_cast<Eigen::Index>(block_.size()))
      throw SolveError("internal: the smoother block's factor has " +
                       std::to_string(factor->rows()) + " rows for a block of " +
                       std::to_string(block_.size()) + " equations");
    factor_ = std::move(factor);
  }

  // The point equations `rows` (sorted; block equations among them stay in the block) swept
  // after all others going down and before them going up (distributed: the rows that read
  // other processes' unknowns, which smooth_sweeps.hpp sweeps process after process). Up stays
  // the transpose of down.
  void put_last(const std::vector<PetscInt>& rows) {
    std::vector<char> is_last(inv_diag_.size(), 0);
    for (PetscInt i : rows)
      if (place_[i] < 0)
        is_last[i] = 1;
    const auto keep = [&](std::vector<PetscInt>& group) {
      std::erase_if(group, [&](PetscInt i) { return is_last[i] != 0; });
    };
    keep(far_);
    keep(near_);
    last_.clear();
    for (PetscInt i = 0; i < static_cast<PetscInt>(is_last.size()); ++i)
      if (is_last[i])
        last_.push_back(i);
  }

  // x <- x + M^-1 (b - A x), `its` times; M = down's or up's splitting. `threads` >= 2: the
  // block's solve beside the far sweep.
  void smooth(const double* b, double* x, bool down, bool zero_guess, PetscInt its, int threads) {
    const auto n = static_cast<PetscInt>(inv_diag_.size());
    if (zero_guess)
      std::fill(x, x + n, 0.0);
    for (PetscInt it = 0; it < its; ++it) {
      if (!down)
        sweep_last(b, x, false);
      sweep_all_but_last(b, x, down, zero_guess && it == 0, threads);
      if (down)
        sweep_last(b, x, true);
    }
  }

  // The parts of one sweep of smooth(): down, all_but_last then last; up, last then
  // all_but_last. `x_is_zero`: x is 0 (down: the block's residual is then b).
  void sweep_all_but_last(const double* b, double* x, bool down, bool x_is_zero, int threads) {
    if (!down)
      sweep(b, x, near_, false);
    block_residual(b, x, down && x_is_zero);
    Eigen::VectorXd dx;
    side_by_side(
        threads, [&] { dx = solve_block(r_); }, [&] { sweep(b, x, far_, down); });
    for (std::size_t k = 0; k < block_.size(); ++k)
      x[block_[k]] += dx[static_cast<Eigen::Index>(k)];
    if (down)
      sweep(b, x, near_, true);
  }
  void sweep_last(const double* b, double* x, bool down) const { sweep(b, x, last_, down); }

  // The same sweeps on a block of columns (row-major: a row's columns side by side), all
  // columns in one pass over the matrix; the block's solves in one CHOLMOD call.
  void smooth_many(const ColumnBlock& b, ColumnBlock& x, bool down, bool zero_guess, int threads) {
    if (zero_guess)
      x.setZero();
    const auto sweep = [&](const std::vector<PetscInt>& rows) {
      Eigen::RowVectorXd s;
      if (down)
        for (PetscInt i : rows)
          relax_many(b, x, i, s);
      else
        for (auto i = rows.rbegin(); i != rows.rend(); ++i)
          relax_many(b, x, *i, s);
    };
    if (!down) {
      sweep(last_);
      sweep(near_);
    }
    Eigen::MatrixXd rb(static_cast<Eigen::Index>(block_.size()), b.cols());
    for (std::size_t k = 0; k < block_.size(); ++k) {
      auto row = rb.row(static_cast<Eigen::Index>(k));
      if (down && zero_guess) {
        row = b.row(block_[k]);
      } else {
        Eigen::RowVectorXd s;
        residual_many(b, x, block_[k], s);
        row = s;
      }
    }
    Eigen::MatrixXd dx;
    side_by_side(
        threads,
        [&] { dx = block_.empty() ? Eigen::MatrixXd() : Eigen::MatrixXd(factor_->solve(rb)); },
        [&] { sweep(far_); });
    for (std::size_t k = 0; k < block_.size(); ++k)
      x.row(block_[k]) += dx.row(static_cast<Eigen::Index>(k));
    if (down) {
      sweep(near_);
      sweep(last_);
    }
  }

private:
  // Everything but the factor: the groups, the diagonal. `place`: block_places.
  BlockSmoother(CsrView a, std::vector<PetscInt> place)
      : row_start_(a.row_start), column_(a.column), value_(a.value), place_(std::move(place)) {
    inv_diag_.assign(a.rows, 0.0);
    for (PetscInt i = 0; i < a.rows; ++i) {
      if (place_[i] >= 0)
        block_.push_back(i);
      for (PetscInt k = row_start_[i]; k < row_start_[i + 1]; ++k)
        if (column_[k] == i && value_[k] > 0)
          inv_diag_[i] = 1 / value_[k];
      if (place_[i] < 0 && inv_diag_[i] == 0)
        throw SolveError("internal: a diagonal entry is not positive");
    }
    for (PetscInt i = 0; i < a.rows; ++i)
      if (place_[i] < 0)
        (couples_to_block(i) ? near_ : far_).push_back(i);
    r_.resize(static_cast<Eigen::Index>(block_.size()));
  }
  // Whether point equation i has an entry in a block column.
  bool couples_to_block(PetscInt i) const {
    for (PetscInt k = row_start_[i]; k < row_start_[i + 1]; ++k)
      if (place_[column_[k]] >= 0)
        return true;
    return false;
  }
  // first() on a thread of its own beside second() on this one, or one after the other.
  template <class First, class Second>
  static void side_by_side(int threads, const First& first, const Second& second) {
    if (threads < 2) {
      first();
      second();
      return;
    }
    std::thread other(first);
    second();
    other.join();
  }
  void residual_many(const ColumnBlock& b, const ColumnBlock& x, PetscInt i,
                     Eigen::RowVectorXd& s) const {
    s = b.row(i);
    subtract_row_products(row_start_, column_, value_, i, x, s.data());
  }
  void relax_many(const ColumnBlock& b, ColumnBlock& x, PetscInt i, Eigen::RowVectorXd& s) const {
    residual_many(b, x, i, s);
    x.row(i) += inv_diag_[i] * s;
  }
  double residual(const double* b, const double* x, PetscInt i) const {
    double sum = b[i];
    for (PetscInt k = row_start_[i]; k < row_start_[i + 1]; ++k)
      sum -= value_[k] * x[column_[k]];
    return sum;
  }
  void relax(const double* b, double* x, PetscInt i) const {
    x[i] += residual(b, x, i) * inv_diag_[i];
  }
  // Gauss-Seidel over `rows`, forward (down) or backward.
  void sweep(const double* b, double* x, const std::vector<PetscInt>& rows, bool down) const {
    if (down)
      for (PetscInt i : rows)
        relax(b, x, i);
    else
      for (auto i = rows.rbegin(); i != rows.rend(); ++i)
        relax(b, x, *i);
  }
  // r_ = (b - A x)_B; with x = 0 it is b.
  void block_residual(const double* b, const double* x, bool x_is_zero) {
    for (std::size_t k = 0; k < block_.size(); ++k)
      r_[static_cast<Eigen::Index>(k)] = x_is_zero ? b[block_[k]] : residual(b, x, block_[k]);
  }
  // K_BB^-1 r (nothing when this process owns none of the block).
  Eigen::VectorXd solve_block(const Eigen::VectorXd& r) const {
    if (block_.empty())
      return {};
    return factor_->solve(r);
  }

  const PetscInt* row_start_;
  const PetscInt* column_;
  const PetscScalar* value_;
  std::vector<PetscInt> place_;              // block_places
  std::vector<PetscInt> block_, far_, near_; // near_: the point equations coupled to the block
  std::vector<PetscInt> last_;               // put_last
  std::vector<double> inv_diag_;
  std::shared_ptr<const BlockFactor> factor_;
  Eigen::VectorXd r_;
};

} // namespace magfem::petsc_module
