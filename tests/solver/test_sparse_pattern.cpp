// The assembled matrix's pattern and scatter table against a dense reference: a wrong or
// missing entry would drop an element coupling from every FE matrix, a wrong slot would add
// it to another entry.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <random>
#include <set>
#include <utility>

#include "solver/sparse_pattern.hpp"

namespace magfem {
namespace {

// Random elements of `per` distinct equations over n equations, some constrained (-1).
std::vector<int> random_elements(int n, int n_elements, int per, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(0, n - 1);
  std::vector<int> eqs;
  for (int e = 0; e < n_elements; ++e) {
    std::set<int> chosen;
    while (static_cast<int>(chosen.size()) < per)
      chosen.insert(pick(rng));
    for (int q : chosen)
      eqs.push_back(rng() % 7 == 0 ? -1 : q);
  }
  return eqs;
}

TEST(SparsePattern, HoldsExactlyTheElementCouplingsAndScattersIntoThem) {
  // More equations than one block of columns (4096), so that blocks are joined.
  const int n = 9000, per = 10, n_elements = 15000;
  const std::vector<int> eqs = random_elements(n, n_elements, per, 7);
  const SparsePattern pattern(n, eqs, per);
  Eigen::SparseMatrix<double> m = pattern.zero_matrix();

  std::set<std::pair<int, int>> expected; // (row, column), lower triangle
  for (int e = 0; e < n_elements; ++e)
    for (int i = 0; i < per; ++i)
      for (int j = 0; j < per; ++j) {
        const int r = eqs[e * per + i], c = eqs[e * per + j];
        if (r >= 0 && c >= 0 && r >= c)
          expected.emplace(r, c);
      }
  std::set<std::pair<int, int>> stored;
  for (int c = 0; c < m.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(m, c); it; ++it)
      stored.emplace(static_cast<int>(it.row()), c);
  EXPECT_EQ(stored, expected);
  EXPECT_EQ(m.nonZeros(), static_cast<Eigen::Index>(expected.size()));

  // Element matrix entry (i, j) = 1000 e + 10 i + j goes to (eq[i], eq[j]); compare with a
  // direct sum (exact: integers well below 2^53).
  std::map<std::pair<int, int>, double> sum;
  std::vector<double> ke(per * per);
  for (int e = 0; e < n_elements; ++e) {
    const int* eq = &eqs[e * per];
    for (int i = 0; i < per; ++i)
      for (int j = 0; j < per; ++j) {
        ke[i * per + j] = 1000.0 * e + 10 * i + j;
        if (eq[i] >= 0 && eq[j] >= 0 && eq[i] >= eq[j])
          sum[{eq[i], eq[j]}] += ke[i * per + j];
      }
    pattern.add(m, e, ke.data());
  }
  for (int c = 0; c < m.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(m, c); it; ++it)
      ASSERT_EQ(it.value(), (sum[{static_cast<int>(it.row()), c}])) << it.row() << ", " << c;
}

} // namespace
} // namespace magfem
