#include "analytic/radial_l1_difference.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/gauss_legendre.hpp"

namespace magfem {

RadialL1 radial_l1_difference(const std::function<double(double)>& reference,
                              const std::function<double(double)>& model,
                              std::vector<double> breakpoints, double y_max, double finest) {
  if (!(finest > 0)) {
    throw std::invalid_argument("radial_l1_difference: finest must be > 0");
  }
  const QuadratureRule g = gauss_legendre(8);
  RadialL1 out;
  auto panel = [&](double lo, double hi) {
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    for (std::size_t i = 0; i < g.x.size(); ++i) {
      const double y = mid + half * g.x[i], w = half * g.w[i];
      const double r = reference(y);
      out.difference += w * std::abs(r - model(y));
      out.reference += w * std::abs(r);
    }
  };
  // [lo, hi] in panels shrinking towards `towards` (one of its ends).
  auto graded = [&](double lo, double hi, bool towards_lo) {
    double far = towards_lo ? hi : lo, near = towards_lo ? lo : hi;
    while (std::abs(far - near) > finest) {
      const double cut = near + 0.25 * (far - near);
      towards_lo ? panel(cut, far) : panel(far, cut);
      far = cut;
    }
    towards_lo ? panel(near, far) : panel(far, near);
  };
  const double last = *std::max_element(breakpoints.begin(), breakpoints.end());
  const double end = y_max > 0 ? y_max : 4 * last;
  breakpoints.push_back(0.0);
  breakpoints.push_back(end);
  std::erase_if(breakpoints, [&](double b) { return b < 0 || b > end; });
  std::sort(breakpoints.begin(), breakpoints.end());
  breakpoints.erase(std::unique(breakpoints.begin(), breakpoints.end()), breakpoints.end());
  for (std::size_t k = 0; k + 1 < breakpoints.size(); ++k) {
    const double lo = breakpoints[k], hi = breakpoints[k + 1], mid = 0.5 * (lo + hi);
    graded(lo, mid, true);
    graded(mid, hi, false);
  }
  if (y_max <= 0) {
    // int_end^inf f(y) dy = int_0^1 f(end / t) end / t^2 dt
    for (int p = 0; p < 4; ++p) {
      const QuadratureRule t = gauss_legendre(16, 0.25 * p, 0.25 * (p + 1));
      for (std::size_t i = 0; i < t.x.size(); ++i) {
        const double y = end / t.x[i], w = t.w[i] * end / (t.x[i] * t.x[i]);
        const double r = reference(y);
        out.difference += w * std::abs(r - model(y));
        out.reference += w * std::abs(r);
      }
    }
  }
  return out;
}

} // namespace magfem
