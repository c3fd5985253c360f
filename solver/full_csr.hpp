#pragma once
// The full CSR of a symmetric matrix given as its lower triangle in CSC (what the assemblers
// hand to the solvers): PETSc's AIJ matrix and pmg's smoother and products read whole rows.
#include <vector>

#include <Eigen/SparseCore>

#include "core/default_init_vector.hpp"

namespace magfem {

struct FullCsr {
  std::vector<int> row_start;    // rows + 1
  DefaultInitVector<int> column; // sorted within each row
  DefaultInitVector<double> value;
};

// `lower`: square, entries on and below the diagonal only (else SolveError). threads: 0 = all
// cores; the result does not depend on it.
FullCsr full_csr_from_lower(const Eigen::SparseMatrix<double>& lower, int threads = 0);

} // namespace magfem
