#include "solver/sparse_pattern.hpp"

#include <algorithm>

#include "core/parallel_blocks.hpp"
#include "core/thread_count.hpp"

namespace magfem {
namespace {

// Elements that hold each equation, as CSR (equation -> elements).
struct EquationElements {
  std::vector<std::size_t> start;
  std::vector<std::size_t> element;
};

EquationElements elements_of_equations(int n_eqs, const std::vector<int>& element_eqs,
                                       int per_element) {
  EquationElements out;
  out.start.assign(static_cast<std::size_t>(n_eqs) + 1, 0);
  for (int e : element_eqs)
    if (e >= 0)
      ++out.start[e + 1];
  for (int i = 0; i < n_eqs; ++i)
    out.start[i + 1] += out.start[i];
  out.element.resize(out.start.back());
  std::vector<std::size_t> next(out.start.begin(), out.start.end() - 1);
  for (std::size_t k = 0; k < element_eqs.size(); ++k)
    if (element_eqs[k] >= 0)
      out.element[next[element_eqs[k]]++] = k / per_element;
  return out;
}

} // namespace

// Built column by column from the elements that share each equation, on all cores: the
// triplet sort this replaces took 5 s of the 32-magnet benchmark's 14 s assembly (1.7 M P2
// tetrahedra). Columns are cut into fixed blocks, so the pattern does not depend on the
// thread count. The scatter table is filled as each column is built, from the rows'
// positions in it (a binary search per element entry afterwards, over columns scattered in
// memory, was a third of the pattern's time), first relative to the column's block and
// then shifted once the blocks' offsets are known.
SparsePattern::SparsePattern(int n_eqs, const std::vector<int>& element_eqs, int per_element)
    : per_element_(per_element) {
  const std::size_t n_elements = element_eqs.size() / per_element;
  const std::size_t pe2 = static_cast<std::size_t>(per_element) * per_element;
  const EquationElements owners = elements_of_equations(n_eqs, element_eqs, per_element);
  const std::size_t block = 4096;
  const std::size_t n_blocks = block_count(static_cast<std::size_t>(n_eqs), block);
  std::vector<std::vector<int>> rows(n_blocks);               // the rows of a block's columns
  std::vector<int> count(static_cast<std::size_t>(n_eqs), 0); // entries per column
  slot_.resize(n_elements * pe2);
  const int threads = available_threads();
  // mark[row] == column + 1 once `row` is in the column: duplicates (an equation shared by
  // the ~20 elements around a vertex) are dropped before the sort, not by it. position[row]:
  // where the row went in its block's list, for the current column.
  std::vector<std::vector<int>> marks(threads), positions(threads);
  parallel_blocks_by_worker(
      n_eqs, block, threads, [&](int worker, std::size_t b, std::size_t lo, std::size_t hi) {
        std::vector<int>& mark = marks[worker];
        std::vector<int>& position = positions[worker];
        if (mark.empty()) {
          mark.assign(static_cast<std::size_t>(n_eqs), 0);
          position.resize(static_cast<std::size_t>(n_eqs));
        }
        std::vector<int> column;
        for (std::size_t j = lo; j < hi; ++j) {
          column.clear();
          const int tag = static_cast<int>(j) + 1;
          for (std::size_t k = owners.start[j]; k < owners.start[j + 1]; ++k) {
            const int* eq = &element_eqs[owners.element[k] * per_element];
            for (int i = 0; i < per_element; ++i)
              if (eq[i] >= static_cast<int>(j) && mark[eq[i]] != tag) {
                mark[eq[i]] = tag;
                column.push_back(eq[i]);
              }
          }
          std::sort(column.begin(), column.end());
          const auto base = static_cast<int>(rows[b].size());
          for (std::size_t r = 0; r < column.size(); ++r)
            position[column[r]] = base + static_cast<int>(r);
          count[j] = static_cast<int>(column.size());
          rows[b].insert(rows[b].end(), column.begin(), column.end());
          // column j, row eq[i] >= j (column-major storage) of every element holding j
          for (std::size_t k = owners.start[j]; k < owners.start[j + 1]; ++k) {
            const std::size_t e = owners.element[k];
            const int* eq = &element_eqs[e * per_element];
            for (int jj = 0; jj < per_element; ++jj)
              if (eq[jj] == static_cast<int>(j))
                for (int i = 0; i < per_element; ++i)
                  if (eq[i] >= static_cast<int>(j))
                    slot_[e * pe2 + i * per_element + jj] = position[eq[i]];
          }
        }
      });
  marks = {};
  positions = {};

  matrix_.resize(n_eqs, n_eqs);
  std::size_t nnz = 0;
  for (const auto& r : rows)
    nnz += r.size();
  matrix_.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = matrix_.outerIndexPtr();
  int* inner = matrix_.innerIndexPtr();
  outer[0] = 0;
  for (int j = 0; j < n_eqs; ++j)
    outer[j + 1] = outer[j] + count[j];
  double* values = matrix_.valuePtr();
  parallel_blocks(n_blocks, 1, threads, [&](std::size_t b, std::size_t, std::size_t) {
    std::copy(rows[b].begin(), rows[b].end(), inner + outer[b * block]);
    std::fill(values + outer[b * block], values + outer[b * block] + rows[b].size(), 0.0);
  });

  parallel_blocks(n_elements, block, threads, [&](std::size_t, std::size_t lo, std::size_t hi) {
    for (std::size_t e = lo; e < hi; ++e) {
      const int* eq = &element_eqs[e * per_element];
      int* slot = &slot_[e * pe2];
      for (int i = 0; i < per_element; ++i)
        for (int j = 0; j < per_element; ++j) {
          int& s = slot[i * per_element + j];
          if (eq[i] < 0 || eq[j] < 0 || eq[i] < eq[j])
            s = -1;
          else
            s += outer[(static_cast<std::size_t>(eq[j]) / block) * block];
        }
    }
  });
}

Eigen::SparseMatrix<double> SparsePattern::zero_matrix() const {
  Eigen::SparseMatrix<double> m(matrix_.rows(), matrix_.cols());
  const Eigen::Index nnz = matrix_.nonZeros();
  m.resizeNonZeros(nnz);
  std::copy(matrix_.outerIndexPtr(), matrix_.outerIndexPtr() + matrix_.outerSize() + 1,
            m.outerIndexPtr());
  const int* from = matrix_.innerIndexPtr();
  int* inner = m.innerIndexPtr();
  double* values = m.valuePtr();
  // Blocks of a million entries: what the copy's threads take in turn.
  parallel_blocks(static_cast<std::size_t>(nnz), std::size_t{1} << 20, available_threads(),
                  [&](std::size_t, std::size_t lo, std::size_t hi) {
                    std::copy(from + lo, from + hi, inner + lo);
                    std::fill(values + lo, values + hi, 0.0);
                  });
  return m;
}

void SparsePattern::add(Eigen::SparseMatrix<double>& m, std::size_t e, const double* ke) const {
  double* values = m.valuePtr();
  const int* slot = &slot_[e * per_element_ * per_element_];
  for (int k = 0; k < per_element_ * per_element_; ++k)
    if (slot[k] >= 0)
      values[slot[k]] += ke[k];
}

} // namespace magfem
