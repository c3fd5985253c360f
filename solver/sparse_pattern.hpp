#pragma once
// Fixed sparsity pattern of a FE matrix with a scatter table, so that repeated assemblies
// (Newton iterations) write straight into the compressed storage without rebuilding it.
// Only the lower triangle is stored (the matrices are symmetric; CHOLMOD reads the lower part).
#include <vector>

#include <Eigen/SparseCore>

#include "core/default_init_vector.hpp"

namespace magfem {

class SparsePattern {
public:
  // element_eqs: for each element, `per_element` equation numbers (-1 = constrained DOF).
  SparsePattern(int n_eqs, const std::vector<int>& element_eqs, int per_element);

  // A matrix with this pattern and zero values (copied on all cores: 420 MB at benchmark32).
  Eigen::SparseMatrix<double> zero_matrix() const;
  // Adds the element matrix ke (per_element x per_element, row major, full) of element e.
  void add(Eigen::SparseMatrix<double>& m, std::size_t e, const double* ke) const;
  // Scatter table of element e: per_element^2 indices into valuePtr (-1 = not stored), row
  // major like ke. For callers that scatter concurrently (atomic adds).
  const int* slots(std::size_t e) const { return &slot_[e * per_element_ * per_element_]; }

private:
  int per_element_;
  Eigen::SparseMatrix<double> matrix_;
  DefaultInitVector<int> slot_; // per element entry: index into valuePtr or -1
};

} // namespace magfem
