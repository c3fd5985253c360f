#include "solver/sparse_pattern.hpp"

namespace magfem {

SparsePattern::SparsePattern(int n_eqs, const std::vector<int>& element_eqs, int per_element)
    : per_element_(per_element) {
  const std::size_t n_elements = element_eqs.size() / per_element;
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(n_elements * per_element * (per_element + 1) / 2);
  for (std::size_t e = 0; e < n_elements; ++e) {
    const int* eq = &element_eqs[e * per_element];
    for (int i = 0; i < per_element; ++i)
      for (int j = 0; j < per_element; ++j)
        if (eq[i] >= 0 && eq[j] >= 0 && eq[i] >= eq[j]) triplets.emplace_back(eq[i], eq[j], 0.0);
  }
  matrix_.resize(n_eqs, n_eqs);
  matrix_.setFromTriplets(triplets.begin(), triplets.end());
  matrix_.makeCompressed();

  slot_.assign(n_elements * per_element * per_element, -1);
  const int* outer = matrix_.outerIndexPtr();
  const int* inner = matrix_.innerIndexPtr();
  for (std::size_t e = 0; e < n_elements; ++e) {
    const int* eq = &element_eqs[e * per_element];
    for (int i = 0; i < per_element; ++i)
      for (int j = 0; j < per_element; ++j) {
        if (eq[i] < 0 || eq[j] < 0 || eq[i] < eq[j]) continue;
        // column eq[j], row eq[i] (column-major storage)
        const int* begin = inner + outer[eq[j]];
        const int* end = inner + outer[eq[j] + 1];
        const int* it = std::lower_bound(begin, end, eq[i]);
        slot_[(e * per_element + i) * per_element + j] = static_cast<int>(it - inner);
      }
  }
}

void SparsePattern::add(Eigen::SparseMatrix<double>& m, std::size_t e, const double* ke) const {
  double* values = m.valuePtr();
  const int* slot = &slot_[e * per_element_ * per_element_];
  for (int k = 0; k < per_element_ * per_element_; ++k)
    if (slot[k] >= 0) values[slot[k]] += ke[k];
}

} // namespace magfem
