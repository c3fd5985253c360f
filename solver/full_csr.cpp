#include "solver/full_csr.hpp"

#include <algorithm>
#include <numeric>

#include "core/input_error.hpp"
#include "core/parallel_blocks.hpp"
#include "core/thread_count.hpp"

namespace magfem {

// CSR of the full symmetric matrix from the CSC lower triangle: row i holds (i, j < i) from
// the lower entries of row i, then (i, j >= i) from column i. Columns come out sorted as PETSc
// requires (columns are visited in order; a column's rows are sorted in a compressed Eigen
// matrix, and any that are not get sorted below). On all cores (2.2 s serially at benchmark32,
// the set-up's main chain): the columns are cut into one range per thread of about equal
// entries; each thread counts, then places, the entries its range gives to the rows' left
// parts, after those of the ranges before it, so every row is what the serial pass made.
FullCsr full_csr_from_lower(const Eigen::SparseMatrix<double>& given, int threads) {
  Eigen::SparseMatrix<double> compressed;
  if (!given.isCompressed()) {
    compressed = given;
    compressed.makeCompressed();
  }
  const Eigen::SparseMatrix<double>& lower = given.isCompressed() ? given : compressed;
  const int n = static_cast<int>(lower.rows());
  const int* outer = lower.outerIndexPtr();
  const int* inner = lower.innerIndexPtr();
  const double* lower_value = lower.valuePtr();
  // Each range keeps a count per row (threads x n ints): at most 8 ranges, so that a many-core
  // machine does not pay gigabytes for it (2 M rows: 64 MB at 8).
  if (threads <= 0)
    threads = std::min(available_threads(), 8);
  FullCsr out;
  std::vector<int>& row_start = out.row_start;
  DefaultInitVector<int>& column = out.column;
  DefaultInitVector<double>& value = out.value;
  std::vector<int> cut(threads + 1, n); // thread t: columns [cut[t], cut[t + 1])
  cut[0] = 0;
  for (int t = 1; t < threads; ++t)
    cut[t] = static_cast<int>(std::upper_bound(outer, outer + n,
                                               static_cast<long long>(outer[n]) * t / threads) -
                              outer) -
             1;
  std::vector<std::vector<int>> left_count(threads, std::vector<int>(n, 0));
  std::vector<char> lower_ok(threads, 1), sorted(threads, 1);
  parallel_blocks(threads, 1, threads, [&](std::size_t t, std::size_t, std::size_t) {
    for (int j = cut[t]; j < cut[t + 1]; ++j)
      for (int k = outer[j]; k < outer[j + 1]; ++k) {
        if (inner[k] < j)
          lower_ok[t] = 0;
        else if (inner[k] > j)
          ++left_count[t][inner[k]];
      }
  });
  if (std::find(lower_ok.begin(), lower_ok.end(), 0) != lower_ok.end())
    throw SolveError("internal: the matrix is not a lower triangle");
  row_start.assign(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    int n_left = 0;
    for (int t = 0; t < threads; ++t) { // left_count[t][i] becomes thread t's first slot
      const int c = left_count[t][i];
      left_count[t][i] = row_start[i] + n_left;
      n_left += c;
    }
    row_start[i + 1] = row_start[i] + n_left + (outer[i + 1] - outer[i]);
  }
  column.resize(row_start[n]);
  value.resize(row_start[n]);
  parallel_blocks(threads, 1, threads, [&](std::size_t t, std::size_t, std::size_t) {
    std::vector<int>& next = left_count[t];
    for (int j = cut[t]; j < cut[t + 1]; ++j) {
      // Row j's right part: column j as it is.
      int right = row_start[j + 1] - (outer[j + 1] - outer[j]);
      for (int k = outer[j]; k < outer[j + 1]; ++k) {
        const int i = inner[k];
        if (k > outer[j] && i <= inner[k - 1])
          sorted[t] = 0;
        if (i > j) {
          column[next[i]] = j;
          value[next[i]++] = lower_value[k];
        }
        column[right] = i;
        value[right++] = lower_value[k];
      }
    }
  });
  if (std::find(sorted.begin(), sorted.end(), 0) == sorted.end())
    return out;
  std::vector<int> order;
  std::vector<int> c;
  std::vector<double> v;
  for (int i = 0; i < n; ++i) {
    const int b = row_start[i], e = row_start[i + 1];
    order.resize(e - b);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](int x, int y) { return column[b + x] < column[b + y]; });
    c.assign(column.begin() + b, column.begin() + e);
    v.assign(value.begin() + b, value.begin() + e);
    for (int k = 0; k < e - b; ++k)
      column[b + k] = c[order[k]], value[b + k] = v[order[k]];
  }
  return out;
}

} // namespace magfem
