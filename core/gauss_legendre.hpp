#pragma once
// Gauss-Legendre quadrature, the one implementation every stage uses (stress-tensor
// surfaces, charge-model faces, harmonic expansions).
#include <vector>

namespace magfem {

// Gauss-Legendre rule on [a, b]: sum_i w_i f(x_i) is exact for polynomials of degree 2q - 1.
// Nodes ascending. Throws std::invalid_argument for q < 1.
struct QuadratureRule {
  std::vector<double> x;
  std::vector<double> w;
};
QuadratureRule gauss_legendre(int q, double a = -1.0, double b = 1.0);

} // namespace magfem
