#include "solver/galerkin_product.hpp"

#include <algorithm>

#include "core/parallel_blocks.hpp"
#include "core/thread_count.hpp"
#include "solver/sparse_row_accumulator.hpp"

namespace magfem {
namespace {

using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// Rows [lo, hi) of P^T A P, appended to `column` / `value`, their lengths to `length`.
struct RowBlock {
  std::vector<int> length, column;
  std::vector<double> value;
};

void product_rows(const int* a_row_start, const int* a_column, const double* a_value,
                  const RowMajor& p, const RowMajor& pt, int lo, int hi, SparseRowAccumulator& acc,
                  RowBlock& out) {
  for (int i = lo; i < hi; ++i) {
    acc.begin_row();
    for (RowMajor::InnerIterator k(pt, i); k; ++k) {
      const int fine_row = static_cast<int>(k.col());
      acc.add_times_p(k.value(), a_column, a_value, a_row_start[fine_row],
                      a_row_start[fine_row + 1], p, [](int c) { return c; });
    }
    out.length.push_back(acc.append_row(out.column, out.value));
  }
}

} // namespace

CsrMatrix galerkin_product(const int* a_row_start, const int* a_column, const double* a_value,
                           const RowMajor& p, int threads, std::size_t block) {
  const int m = static_cast<int>(p.cols());
  const RowMajor pt = p.transpose(); // P's columns as rows
  std::vector<RowBlock> blocks(block_count(static_cast<std::size_t>(m), block));
  if (threads <= 0)
    threads = available_threads();
  std::vector<SparseRowAccumulator> scratch;
  for (int t = 0; t < threads; ++t)
    scratch.emplace_back(m);
  parallel_blocks_by_worker(static_cast<std::size_t>(m), block, threads,
                            [&](int worker, std::size_t b, std::size_t lo, std::size_t hi) {
                              product_rows(a_row_start, a_column, a_value, p, pt,
                                           static_cast<int>(lo), static_cast<int>(hi),
                                           scratch[static_cast<std::size_t>(worker)], blocks[b]);
                            });
  CsrMatrix c;
  c.rows = c.cols = m;
  c.row_start.reserve(static_cast<std::size_t>(m) + 1);
  c.row_start.push_back(0);
  for (const RowBlock& b : blocks) {
    for (int len : b.length)
      c.row_start.push_back(c.row_start.back() + len);
    c.column.insert(c.column.end(), b.column.begin(), b.column.end());
    c.value.insert(c.value.end(), b.value.begin(), b.value.end());
  }
  return c;
}

CsrMatrix partial_galerkin_product(int n_rows, const std::vector<CsrRowBlock>& blocks,
                                   const int* row_equation, const RowMajor& p,
                                   std::vector<int>& coarse_rows) {
  const int m = static_cast<int>(p.cols());
  const int* p_start = p.outerIndexPtr();
  const int* p_col = p.innerIndexPtr();
  const double* p_val = p.valuePtr();
  // P's entries on these rows, by coarse unknown (then row: a fixed order of the sums).
  struct Entry {
    int coarse, row;
    double weight;
  };
  std::vector<Entry> entries;
  for (int r = 0; r < n_rows; ++r)
    for (int k = p_start[row_equation[r]]; k < p_start[row_equation[r] + 1]; ++k)
      entries.push_back({p_col[k], r, p_val[k]});
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.coarse != b.coarse ? a.coarse < b.coarse : a.row < b.row;
  });
  SparseRowAccumulator acc(m);
  CsrMatrix c;
  c.cols = m;
  c.row_start.push_back(0);
  coarse_rows.clear();
  for (std::size_t first = 0; first < entries.size();) {
    const int i = entries[first].coarse;
    acc.begin_row();
    std::size_t k = first;
    for (; k < entries.size() && entries[k].coarse == i; ++k)
      for (const CsrRowBlock& b : blocks)
        acc.add_times_p(entries[k].weight, b.column, b.value, b.row_start[entries[k].row],
                        b.row_start[entries[k].row + 1], p,
                        [&b](int c) { return b.column_equation[c]; });
    first = k;
    acc.append_row(c.column, c.value);
    c.row_start.push_back(static_cast<int>(c.column.size()));
    coarse_rows.push_back(i);
  }
  c.rows = static_cast<int>(coarse_rows.size());
  return c;
}

} // namespace magfem
