#include "sources/source_quadrature.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>

namespace magfem {

const QuadratureRule& cached_gauss(int n) {
  static const std::array<QuadratureRule, max_cached_gauss_order> rules = [] {
    std::array<QuadratureRule, max_cached_gauss_order> r;
    for (int q = 1; q <= max_cached_gauss_order; ++q) {
      r[static_cast<std::size_t>(q - 1)] = gauss_legendre(q);
    }
    return r;
  }();
  return rules[static_cast<std::size_t>(std::clamp(n, 1, max_cached_gauss_order) - 1)];
}

int gauss_order_for(double mid, double half, double re, double im, double tol, int n_min, int n_max,
                    int poly_degree, double poly_root) {
  if (!(half > 0)) {
    return n_min;
  }
  // The ellipse with foci -1, 1 through w: semi-major axis (|w - 1| + |w + 1|) / 2 = cosh(ln rho).
  const double x = (re - mid) / half, y = im / half;
  const double a =
      0.5 * (std::sqrt((x - 1.0) * (x - 1.0) + y * y) + std::sqrt((x + 1.0) * (x + 1.0) + y * y));
  const double rho_max = a + std::sqrt(std::max(a * a - 1.0, 0.0));
  if (!(rho_max > 1.0 + 1e-12)) {
    return n_max + 1;
  }
  // Error ~ M(rho) rho^-2n, M(rho) the integrand's size on the ellipse relative to the
  // interval: 1 + 1/(rho - 1) from the singularity, and (|z - root| / |x - root|)^degree from a
  // polynomial factor (a^2 of a loop, the Jacobian r). Since ln M grows at most like
  // degree ln rho, slower than the 2 n ln rho it is compared with, the largest ellipse is the
  // best. The extra 2 is the margin measured in tests/sources.
  double cost = std::log(1.0 / tol) + 2.0 + std::log(1.0 + 1.0 / (rho_max - 1.0));
  if (poly_degree > 0) {
    const double semi_major = 0.5 * half * (rho_max + 1.0 / rho_max);
    const double dist_root = std::max(std::abs(mid - poly_root) - half, 0.05 * half);
    cost += poly_degree * std::log((std::abs(mid - poly_root) + semi_major) / dist_root);
  }
  const double best = cost / (2.0 * std::log(rho_max));
  if (!(best <= n_max)) {
    return n_max + 1;
  }
  return std::max(n_min, static_cast<int>(std::ceil(best)));
}

int gauss_order_entire(double type, double half, double tol, int n_min, int n_max) {
  const double x = type * half;
  // A factor 100 of margin: the bound's constant and the size of the rest of the integrand.
  double term = 100.0;
  for (int n = 1; n <= n_max; ++n) {
    term *= x * x / ((2.0 * n - 1.0) * (2.0 * n));
    if (term <= tol) {
      return std::max(n, n_min);
    }
  }
  return n_max + 1;
}

namespace {

// Appends n Gauss points on [a, b] (any order of a and b; weights positive).
void append_gauss(double a, double b, int n, std::vector<Node1>& out) {
  const QuadratureRule& g = cached_gauss(n);
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (std::size_t i = 0; i < g.x.size(); ++i) {
    out.push_back({mid + half * g.x[i], std::abs(half) * g.w[i]});
  }
}

// One side of a graded rule: from x_s (singular end) to x_end.
void append_graded_side(double x_s, double x_end, double width, int n, double ratio, int min_panels,
                        bool square_innermost, std::vector<Node1>& out) {
  const double length = std::abs(x_end - x_s);
  if (length <= 0) {
    return;
  }
  int panels = min_panels;
  if (width > 0 && width < length) {
    panels = std::max(
        panels, 1 + static_cast<int>(std::ceil(std::log(length / width) / std::log(1.0 / ratio))));
  } else if (width <= 0) {
    panels = std::max(panels, 1);
  }
  panels = std::min(panels, 40);
  double outer = x_end;
  double f = 1.0;
  for (int k = 0; k < panels; ++k) {
    const bool last = k == panels - 1;
    f *= ratio;
    const double inner = last ? x_s : x_s + f * (x_end - x_s);
    if (last && square_innermost) {
      // x = x_s + (outer - x_s) sigma^2: x log x terms in the innermost panel become
      // sigma^3 log sigma, which Gauss integrates to much higher order.
      const QuadratureRule& g = cached_gauss(n);
      for (std::size_t i = 0; i < g.x.size(); ++i) {
        const double sigma = 0.5 * (1.0 + g.x[i]);
        out.push_back(
            {x_s + (outer - x_s) * sigma * sigma, std::abs(outer - x_s) * g.w[i] * sigma});
      }
    } else {
      append_gauss(inner, outer, n, out);
    }
    outer = inner;
  }
}

} // namespace

void append_graded_rule(double a, double b, double x_s, double width, int n, double ratio,
                        int min_panels, bool square_innermost, std::vector<Node1>& out) {
  x_s = std::clamp(x_s, std::min(a, b), std::max(a, b));
  append_graded_side(x_s, a, width, n, ratio, min_panels, square_innermost, out);
  append_graded_side(x_s, b, width, n, ratio, min_panels, square_innermost, out);
}

namespace {

// Tensor Gauss on the rectangle [u0,u1] x [v0,v1] (any orientation), n x n points.
void append_tensor(double u0, double u1, double v0, double v1, int n, std::vector<Node2>& out) {
  const QuadratureRule& g = cached_gauss(n);
  const double hu = 0.5 * (u1 - u0), hv = 0.5 * (v1 - v0);
  const double mu = 0.5 * (u0 + u1), mv = 0.5 * (v0 + v1);
  const double area = std::abs(hu * hv);
  for (std::size_t i = 0; i < g.x.size(); ++i) {
    for (std::size_t j = 0; j < g.x.size(); ++j) {
      out.push_back({mu + hu * g.x[i], mv + hv * g.x[j], area * g.w[i] * g.w[j]});
    }
  }
}

// The sub-rectangle with the singular point at its corner (uc, vc) and extents du, dv (signed).
// A physically square part at the corner is integrated in Duffy coordinates; the rest of a
// long sub-rectangle is cut into panels doubling in length away from the corner, each at a
// distance from the singular point at least its own length, where tensor Gauss converges fast.
void append_corner_rect(double uc, double vc, double du, double dv, const NearPoint& p,
                        std::vector<Node2>& out) {
  const double lu = std::abs(du) * p.su, lv = std::abs(dv) * p.sv;
  const double side = std::min(lu, lv);
  if (side <= 1e-12 * std::max(lu, lv)) {
    return; // the split point lies on (or within 1e-12 of) this edge: nothing to integrate
  }
  // Square part.
  const double su = std::copysign(side / p.su, du), sv = std::copysign(side / p.sv, dv);
  std::vector<Node1> radial;
  radial.reserve(64);
  append_graded_rule(0.0, 1.0, 0.0, p.width / side, p.n, 0.2, 1, p.singular, radial);
  const QuadratureRule& g = cached_gauss(p.n);
  const double jac = std::abs(su * sv);
  for (const Node1& s : radial) {
    for (std::size_t j = 0; j < g.x.size(); ++j) {
      const double t = 0.5 * (1.0 + g.x[j]), wt = 0.5 * g.w[j];
      const double w = s.w * wt * s.x * jac;
      // Triangle (C, C + su e_u, C + su e_u + sv e_v) and its mirror across the diagonal.
      out.push_back({uc + s.x * su, vc + s.x * t * sv, w});
      out.push_back({uc + s.x * t * su, vc + s.x * sv, w});
    }
  }
  // Strip beyond the square along the longer side.
  const bool along_u = lu > lv;
  const double total = along_u ? lu : lv;
  double start = side;
  while (start < total * (1 - 1e-12)) {
    const double end = std::min(2 * start, total);
    if (along_u) {
      append_tensor(uc + std::copysign(start / p.su, du), uc + std::copysign(end / p.su, du), vc,
                    vc + sv, p.n, out);
    } else {
      append_tensor(uc, uc + su, vc + std::copysign(start / p.sv, dv),
                    vc + std::copysign(end / p.sv, dv), p.n, out);
    }
    start = end;
  }
}

} // namespace

void append_near_rule(const ParamRect& rect, const NearPoint& p, std::vector<Node2>& out) {
  const double uc = std::clamp(p.u, rect.u0, rect.u1);
  const double vc = std::clamp(p.v, rect.v0, rect.v1);
  for (const double ue : {rect.u0, rect.u1}) {
    for (const double ve : {rect.v0, rect.v1}) {
      append_corner_rect(uc, vc, ue - uc, ve - vc, p, out);
    }
  }
}

} // namespace magfem
