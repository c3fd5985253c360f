#include "core/gauss_legendre.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/constants.hpp"

namespace magfem {

QuadratureRule gauss_legendre(int q, double a, double b) {
  if (q < 1) {
    throw std::invalid_argument("gauss_legendre: need at least one node, got " + std::to_string(q));
  }
  QuadratureRule rule;
  rule.x.resize(static_cast<std::size_t>(q));
  rule.w.resize(static_cast<std::size_t>(q));
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (int i = 0; i < (q + 1) / 2; ++i) {
    // Newton on P_q from the classical asymptotic guess; converges in a few steps.
    double t = std::cos(pi * (i + 0.75) / (q + 0.5));
    double dp = 1.0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1.0, p1 = t;
      for (int k = 2; k <= q; ++k) {
        const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = q * (t * p1 - p0) / (t * t - 1.0);
      const double dt = p1 / dp;
      t -= dt;
      if (std::abs(dt) < 1e-16) {
        break;
      }
    }
    const double w = 2.0 / ((1.0 - t * t) * dp * dp);
    const auto lo = static_cast<std::size_t>(i), hi = static_cast<std::size_t>(q - 1 - i);
    rule.x[lo] = mid - half * t;
    rule.x[hi] = mid + half * t;
    rule.w[lo] = rule.w[hi] = half * w;
  }
  return rule;
}

} // namespace magfem
