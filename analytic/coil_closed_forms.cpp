#include "analytic/coil_closed_forms.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <vector>

#include "core/constants.hpp"
#include "core/gauss_legendre.hpp"
#include "sources/loop_field.hpp"

namespace magfem {

double coaxial_coil_axial_H(const CoaxialCoil& coil, double current, double z) {
  const double length = coil.z_max - coil.z_min;
  const double ni = coil.turns * current;
  const double u1 = z - coil.z_min, u2 = z - coil.z_max;
  if (coil.r_outer == coil.r_inner) {
    const double a = coil.r_inner;
    return 0.5 * ni / length * (u1 / std::hypot(a, u1) - u2 / std::hypot(a, u2));
  }
  // u ln((r_o + sqrt(r_o^2 + u^2)) / (r_i + sqrt(r_i^2 + u^2))) = u (asinh(r_o/|u|) -
  // asinh(r_i/|u|))
  auto f = [&](double u) {
    if (u == 0) {
      return 0.0;
    }
    const double au = std::abs(u);
    return u * (std::asinh(coil.r_outer / au) - std::asinh(coil.r_inner / au));
  };
  const double j = ni / ((coil.r_outer - coil.r_inner) * length);
  return 0.5 * j * (f(u1) - f(u2));
}

double nagaoka_coefficient(double radius, double length) {
  const double k2 = 4 * radius * radius / (4 * radius * radius + length * length);
  const double k = std::sqrt(k2), kc2 = 1 - k2, kc = std::sqrt(kc2);
  const double K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
  return 4.0 / (3.0 * pi * kc) * (kc2 / k2 * (K - E) + E - k);
}

double current_sheet_self_inductance(double radius, double length, double turns) {
  return mu0 * pi * radius * radius * turns * turns / length * nagaoka_coefficient(radius, length);
}

namespace {

using Function2 = std::function<double(double, double)>;

// Appends the Gauss points of [lo, hi] to (x, w).
void append_gauss(double lo, double hi, int n, std::vector<double>& x, std::vector<double>& w) {
  const QuadratureRule g = gauss_legendre(n, lo, hi);
  x.insert(x.end(), g.x.begin(), g.x.end());
  w.insert(w.end(), g.w.begin(), g.w.end());
}

// Panels on [0, length] shrinking geometrically (ratio 0.15) towards 0 down to 1e-13 length,
// for integrands with a logarithmic singularity (times a smooth factor) at 0.
void append_graded(double length, int n, std::vector<double>& x, std::vector<double>& w) {
  double hi = length;
  while (hi > 1e-13 * length) {
    append_gauss(0.15 * hi, hi, n, x, w);
    hi *= 0.15;
  }
  append_gauss(0.0, hi, n, x, w);
}

// int_0^W int_0^H f(u, v) dv du for f with a logarithmic singularity at (0, 0): the square of side
// min(W, H) at the corner in Duffy coordinates (u, v) = s (m, t m) and (t m, m), where the
// singularity becomes s log s, graded in s; the rest of the rectangle in panels that double in
// length away from the corner, each at least its own length from the singularity.
double corner_singular_integral(double W, double H, const Function2& f, int n) {
  const double m = std::min(W, H);
  std::vector<double> sx, sw, tx, tw;
  append_graded(1.0, n, sx, sw);
  append_gauss(0.0, 1.0, n, tx, tw);
  double sum = 0;
  for (std::size_t i = 0; i < sx.size(); ++i) {
    for (std::size_t j = 0; j < tx.size(); ++j) {
      const double s = sx[i], t = tx[j], w = sw[i] * tw[j] * s * m * m;
      sum += w * (f(s * m, s * t * m) + f(s * t * m, s * m));
    }
  }
  const bool along_u = W > H;
  const double total = along_u ? W : H;
  for (double start = m; start < total * (1 - 1e-14);) {
    const double end = std::min(2 * start, total);
    std::vector<double> px, pw, qx, qw;
    append_gauss(start, end, n, px, pw);
    append_gauss(0.0, m, n, qx, qw);
    for (std::size_t i = 0; i < px.size(); ++i) {
      for (std::size_t j = 0; j < qx.size(); ++j) {
        sum += pw[i] * qw[j] * (along_u ? f(px[i], qx[j]) : f(qx[j], px[i]));
      }
    }
    start = end;
  }
  return sum;
}

} // namespace

// L = (N / A)^2 int dA1 int dA2 M(a1, a2, z2 - z1). The z double integral of a function of the
// difference is int (l - |d|) f(d) dd, even in d; M is symmetric in a1, a2. With
// a1 = s - delta/2, a2 = s + delta/2 (unit Jacobian):
//   L = 4 (N / A)^2 int_0^w ddelta int_0^l dd (l - d) int_{r_i + delta/2}^{r_o - delta/2} M ds,
// singular (logarithmically) only at delta = d = 0.
double coaxial_coil_self_inductance(const CoaxialCoil& coil, int order) {
  const double length = coil.z_max - coil.z_min;
  const double w = coil.r_outer - coil.r_inner;
  if (!(length > 0 && w >= 0 && coil.r_inner >= 0)) {
    throw std::invalid_argument("coaxial_coil_self_inductance: bad cross-section");
  }
  const double n2 = coil.turns * coil.turns;
  if (w == 0) {
    // Current sheet: L = (N / l)^2 2 int_0^l (l - d) M(a, a, d) dd; graded towards the
    // logarithmic singularity at d = 0 below the radius, panels doubling beyond it (M decays
    // on the scale of the radius).
    std::vector<double> x, wt;
    const double near = std::min(coil.r_inner, length);
    append_graded(near, order, x, wt);
    for (double start = near; start < length * (1 - 1e-14); start *= 2) {
      append_gauss(start, std::min(2 * start, length), order, x, wt);
    }
    double sum = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      sum += wt[i] * (length - x[i]) * loop_mutual_inductance(coil.r_inner, coil.r_inner, x[i]);
    }
    return n2 / (length * length) * 2.0 * sum;
  }
  const QuadratureRule g = gauss_legendre(order + 4);
  auto inner = [&](double delta, double d) {
    const double lo = coil.r_inner + 0.5 * delta, hi = coil.r_outer - 0.5 * delta;
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    double s = 0;
    for (std::size_t k = 0; k < g.x.size(); ++k) {
      const double sigma = mid + half * g.x[k];
      s += g.w[k] * loop_mutual_inductance(sigma - 0.5 * delta, sigma + 0.5 * delta, d);
    }
    return (length - d) * half * s;
  };
  const double area = w * length;
  return 4.0 * n2 / (area * area) * corner_singular_integral(w, length, inner, order);
}

namespace {

// Radial rule of a coil, weights normalized to 1 (a sheet is a single radius).
void radial_rule(const CoaxialCoil& c, int panels, int n, std::vector<double>& x,
                 std::vector<double>& w) {
  if (c.r_outer == c.r_inner) {
    x = {c.r_inner};
    w = {1.0};
    return;
  }
  const double width = c.r_outer - c.r_inner;
  for (int p = 0; p < panels; ++p) {
    append_gauss(c.r_inner + width * p / panels, c.r_inner + width * (p + 1) / panels, n, x, w);
  }
  for (double& wi : w) {
    wi /= width;
  }
}

// (N_a N_b / (l_a l_b)) int int da1 da2 (weights normalized over each cross-section's radius)
// int K(d) kernel(a1, a2, d) dd, K(d) = length of {z1 in a : z1 + d in b}, piecewise linear with
// kinks at the four differences of the ends; refined (panels doubled) until two levels agree.
double coaxial_pair_integral(const CoaxialCoil& a, const CoaxialCoil& b,
                             double (*kernel)(double, double, double)) {
  const double overlap_r = std::min(a.r_outer, b.r_outer) - std::max(a.r_inner, b.r_inner);
  const double overlap_z = std::min(a.z_max, b.z_max) - std::max(a.z_min, b.z_min);
  if (overlap_r >= 0 && overlap_z >= 0) {
    throw std::invalid_argument("coaxial_pair_integral: the cross-sections touch or overlap");
  }
  std::vector<double> kinks = {b.z_min - a.z_max, b.z_min - a.z_min, b.z_max - a.z_max,
                               b.z_max - a.z_min};
  std::sort(kinks.begin(), kinks.end());
  auto weight = [&](double d) {
    return std::max(0.0, std::min(a.z_max, b.z_max - d) - std::max(a.z_min, b.z_min - d));
  };
  constexpr int n = 16;
  double previous = 0;
  for (int panels = 1; panels <= 64; panels *= 2) {
    std::vector<double> xa, wa, xb, wb, xd, wd;
    radial_rule(a, panels, n, xa, wa);
    radial_rule(b, panels, n, xb, wb);
    for (std::size_t k = 0; k + 1 < kinks.size(); ++k) {
      if (kinks[k + 1] > kinks[k]) {
        for (int p = 0; p < panels; ++p) {
          const double h = (kinks[k + 1] - kinks[k]) / panels;
          append_gauss(kinks[k] + p * h, kinks[k] + (p + 1) * h, n, xd, wd);
        }
      }
    }
    double sum = 0;
    for (std::size_t i = 0; i < xa.size(); ++i) {
      for (std::size_t j = 0; j < xb.size(); ++j) {
        double s = 0;
        for (std::size_t k = 0; k < xd.size(); ++k) {
          s += wd[k] * weight(xd[k]) * kernel(xa[i], xb[j], xd[k]);
        }
        sum += wa[i] * wb[j] * s;
      }
    }
    const double value = a.turns * b.turns * sum / ((a.z_max - a.z_min) * (b.z_max - b.z_min));
    if (panels > 1 && std::abs(value - previous) <= 1e-11 * std::abs(value)) {
      return value;
    }
    previous = value;
  }
  return previous;
}

} // namespace

double coaxial_mutual_inductance(const CoaxialCoil& a, const CoaxialCoil& b) {
  return coaxial_pair_integral(a, b, &loop_mutual_inductance);
}

double coaxial_axial_force(const CoaxialCoil& a, const CoaxialCoil& b, double current_a,
                           double current_b) {
  return current_a * current_b * coaxial_pair_integral(a, b, &loop_mutual_inductance_dd);
}

} // namespace magfem
