#pragma once
// One row of a sparse sum at a time, over m columns: a dense accumulator and the list of the
// columns the row touched, so that a row costs its entries, not m. Used by the Galerkin
// products (galerkin_product.hpp), serial and distributed, which each sum rows in a fixed
// order: entries add in the order `add` sees them, so the same bits every run.
#include <algorithm>
#include <vector>

#include <Eigen/SparseCore>

namespace magfem {

class SparseRowAccumulator {
public:
  explicit SparseRowAccumulator(int m)
      : sum_(static_cast<std::size_t>(m), 0.0), row_of_(static_cast<std::size_t>(m), -1) {}

  // Starts a new row; what earlier rows added is forgotten.
  void begin_row() {
    ++row_;
    touched_.clear();
  }

  void add(int j, double v) {
    const auto c = static_cast<std::size_t>(j);
    if (row_of_[c] != row_) {
      row_of_[c] = row_;
      sum_[c] = 0;
      touched_.push_back(j);
    }
    sum_[c] += v;
  }

  // Adds weight * A(r, :) P, A(r, :) being the CSR entries [first, last) and P's row for
  // column c being p_row(c).
  template <class PRowOf>
  void add_times_p(double weight, const int* column, const double* value, int first, int last,
                   const Eigen::SparseMatrix<double, Eigen::RowMajor>& p, const PRowOf& p_row) {
    const int* p_start = p.outerIndexPtr();
    const int* p_col = p.innerIndexPtr();
    const double* p_val = p.valuePtr();
    for (int e = first; e < last; ++e) {
      const double v = weight * value[e];
      const int l = p_row(column[e]);
      for (int q = p_start[l]; q < p_start[l + 1]; ++q)
        add(p_col[q], v * p_val[q]);
    }
  }

  // Appends the row's entries, columns ascending; returns how many.
  int append_row(std::vector<int>& column, std::vector<double>& value) {
    std::sort(touched_.begin(), touched_.end());
    for (int j : touched_) {
      column.push_back(j);
      value.push_back(sum_[static_cast<std::size_t>(j)]);
    }
    return static_cast<int>(touched_.size());
  }

private:
  std::vector<double> sum_;
  std::vector<long> row_of_; // the row that last touched each column
  std::vector<int> touched_;
  long row_ = -1;
};

} // namespace magfem
