#pragma once
// Orders of tensor Gauss-Legendre rules on charge-domain boxes from their a priori error, shared by
// the face-pair interaction (pair_interaction.hpp) and the exterior-field interaction
// (exterior_field_interaction.hpp):
//  - a kernel singular `rho` box radii from the box centre: the Bernstein-ellipse rate
//    (rho + sqrt(rho^2 - 1))^(-2n) of an n-point rule;
//  - the box's own angles: far from the singularity the kernel is nearly constant, but the
//    density, the Jacobian and the position are sines and cosines of the angular parameters;
//    an n-point rule over a half-width h integrates such a product with relative error about
//    c_n (2 h')^(2n), c_n = (n!)^4 / ((2n + 1) ((2n)!)^3) (the remainder term), taking
//    h' = 3 h: the density (M.n), the Jacobian and the position each bring one trigonometric
//    factor of the angle, so the product's derivatives grow like 3^k.
#include <algorithm>
#include <array>
#include <cmath>

namespace magfem {

// ln c_n, tabulated: the cubature asks for it once or more per box pair.
inline double gauss_log_c(int n) {
  constexpr int n_table = 64;
  auto log_c = [](int m) {
    return 4 * std::lgamma(m + 1.0) - std::log(2.0 * m + 1) - 3 * std::lgamma(2.0 * m + 1);
  };
  static const std::array<double, n_table> table = [&] {
    std::array<double, n_table> t{};
    for (int m = 0; m < n_table; ++m)
      t[m] = log_c(m);
    return t;
  }();
  return n >= 0 && n < n_table ? table[n] : log_c(n);
}

inline double gauss_angle_error(double half_angle, int n) {
  if (half_angle == 0)
    return 0;
  return std::exp(gauss_log_c(n) + 2.0 * n * std::log(6 * half_angle));
}

// Smallest order in [min_order, max_order] whose two errors are below tolerance, or
// max_order + 1 if none is.
inline int gauss_order(double tolerance, double rho, double half_angle, int min_order,
                       int max_order) {
  int n = min_order;
  if (rho <= 1.0 + 1e-12)
    return max_order + 1;
  const double kernel = std::ceil(std::log(1.0 / tolerance) / (2.0 * std::acosh(rho)));
  n = static_cast<int>(std::clamp(kernel, double(min_order), double(max_order + 1)));
  while (n <= max_order && gauss_angle_error(half_angle, n) > tolerance)
    ++n;
  return n;
}

} // namespace magfem
