#include "sources/zonal_expansion.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "core/constants.hpp"
#include "sources/source_quadrature.hpp"

namespace magfem {

ZonalExpansion::ZonalExpansion(Kind kind, double center, double radius,
                               std::vector<double> coefficients, double tolerance, int max_terms)
    : kind_(kind), center_(center), radius_(radius), tolerance_(tolerance),
      coefficients_(std::move(coefficients)) {
  const int n = static_cast<int>(coefficients_.size()) - 1;
  if (n < 2 || !(radius > 0) || coefficients_[1] == 0.0) {
    coefficients_.clear();
    return;
  }
  max_terms_ = std::min(max_terms, n - 1);
  tail_.assign(static_cast<std::size_t>(n + 2), 0.0);
  radial_.assign(static_cast<std::size_t>(n + 1), 0.0);
  const double c1 = std::abs(coefficients_[1]);
  for (int m = n; m >= 1; --m) {
    const auto i = static_cast<std::size_t>(m);
    tail_[i] = std::max(tail_[i + 1], 2.0 * (m + 1) * std::abs(coefficients_[i]) / c1);
    radial_[i] = (kind == Kind::exterior ? m + 1.0 : -1.0 * m) * coefficients_[i];
  }
  // Largest q at which some m <= max_terms_ satisfies tail_[m+1] q^m / (1 - q) <= tolerance
  // (the stopping test of evaluate()), by bisection: the test is monotone in q.
  auto reachable = [&](double q) {
    double qm = 1.0;
    for (int m = 1; m <= max_terms_; ++m) {
      qm *= q;
      if (tail_[static_cast<std::size_t>(m + 1)] * qm <= tolerance_ * (1.0 - q)) {
        return true;
      }
    }
    return false;
  };
  double lo = 0.0, hi = 1.0;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (reachable(mid) ? lo : hi) = mid;
  }
  q_limit_ = lo;
}

namespace {

// Three-term recurrence factors of the Legendre polynomials,
// P_{m+1} = a_m t P_m - b_m P_{m-1}, a_m = (2m+1)/(m+1), b_m = m/(m+1), tabulated so that the
// evaluation loop has no division.
struct LegendreRecurrence {
  std::vector<double> a, b;
};
const LegendreRecurrence& legendre_recurrence() {
  static const LegendreRecurrence r = [] {
    LegendreRecurrence t;
    for (int m = 0; m <= 2048; ++m) { // beyond the largest expansion_terms allowed
      t.a.push_back((2.0 * m + 1.0) / (m + 1.0));
      t.b.push_back(m / (m + 1.0));
    }
    return t;
  }();
  return r;
}

} // namespace

bool ZonalExpansion::evaluate(double rho, double z, MeridianField& h) const {
  if (coefficients_.empty()) {
    return false;
  }
  z -= center_;
  const double r2 = rho * rho + z * z;
  const double r = std::sqrt(r2);
  const bool exterior = kind_ == Kind::exterior;
  const double q = exterior ? radius_ / r : r / radius_;
  if (!(q <= q_limit_)) {
    return false;
  }
  const double t = r > 0 ? z / r : 1.0, s = r > 0 ? rho / r : 0.0;
  const double stop = tolerance_ * (1.0 - q);
  const LegendreRecurrence& rec = legendre_recurrence();
  // P_m(t) and P_m'(t) by their recurrences, m = 1, 2, ...; term m carries q^m (exterior) or
  // q^(m-1) (interior), the stopping test q^m.
  double p_prev = 1.0, p = t, dp_prev = 0.0, dp = 1.0;
  double qa = exterior ? q : 1.0;
  const double qs = exterior ? 1.0 : q;
  double hr = 0.0, ht = 0.0;
  const double* c = coefficients_.data();
  const double* cr = radial_.data();
  const double* tail = tail_.data();
  for (int m = 1; m <= max_terms_; ++m) {
    hr += cr[m] * qa * p;
    ht += c[m] * qa * dp;
    if (tail[m + 1] * qa * qs <= stop) {
      break;
    }
    const double p_next =
        rec.a[static_cast<std::size_t>(m)] * t * p - rec.b[static_cast<std::size_t>(m)] * p_prev;
    const double dp_next = dp_prev + (2 * m + 1) * p;
    p_prev = p;
    p = p_next;
    dp_prev = dp;
    dp = dp_next;
    qa *= q;
  }
  if (exterior) {
    hr /= r2;
    ht /= r2;
  }
  ht *= s;
  h.h_rho = hr * s + ht * t;
  h.h_z = hr * t - ht * s;
  return true;
}

namespace {

// Legendre P_m and P_m' at t for m = 0..n.
void legendre_with_derivative(double t, int n, std::vector<double>& p, std::vector<double>& dp) {
  p.assign(static_cast<std::size_t>(n + 2), 0.0);
  dp.assign(static_cast<std::size_t>(n + 2), 0.0);
  p[0] = 1.0;
  p[1] = t;
  dp[1] = 1.0;
  for (int m = 1; m <= n; ++m) {
    const auto i = static_cast<std::size_t>(m);
    p[i + 1] = ((2 * m + 1) * t * p[i] - m * p[i - 1]) / (m + 1);
    dp[i + 1] = dp[i - 1] + (2 * m + 1) * p[i];
  }
}

// Composite 20-point Gauss on [a, b] with `panels` equal panels.
std::vector<Node1> composite_rule(double a, double b, int panels) {
  std::vector<Node1> out;
  const QuadratureRule& g = cached_gauss(20);
  const double h = (b - a) / panels;
  for (int k = 0; k < panels; ++k) {
    const double lo = a + k * h;
    for (std::size_t i = 0; i < g.x.size(); ++i) {
      out.push_back({lo + 0.5 * h * (1.0 + g.x[i]), 0.5 * h * g.w[i]});
    }
  }
  return out;
}

} // namespace

// A loop of radius a at height z0 (relative to the centre; R0 = sqrt(a^2 + z0^2), t0 = z0 / R0)
// carrying I has on its axis H_z = I a^2 / (2 (a^2 + (z - z0)^2)^{3/2}), whose expansions in
// powers of R0/z and z/R0 follow from the generating function of P_m' (Gegenbauer C^{3/2}):
//   exterior: c_m R^m = I a^2 R0^(m-1) P_m'(t0) / (2 (m+1)),
//   interior: c_m R^-(m-1) = -I a^2 P_m'(t0) / (2 m R0^(m+2)).
std::vector<double> exterior_coefficients(const std::vector<LoopSample>& loops, double center,
                                          double radius, int n_terms) {
  std::vector<double> coef(static_cast<std::size_t>(n_terms + 1), 0.0), p, dp;
  for (const LoopSample& l : loops) {
    const double z0 = l.z0 - center;
    const double r0 = std::hypot(l.a, z0);
    if (!(r0 > 0)) {
      continue;
    }
    legendre_with_derivative(z0 / r0, n_terms, p, dp);
    double ratio = 1.0; // (R0 / R)^(m-1)
    for (int m = 1; m <= n_terms; ++m) {
      coef[static_cast<std::size_t>(m)] += l.current * l.a * l.a / radius * ratio *
                                           dp[static_cast<std::size_t>(m)] / (2.0 * (m + 1));
      ratio *= r0 / radius;
    }
  }
  return coef;
}

// On a spherical coil a = r sin(alpha), R0 = r, t0 = cos(alpha), dI = J r dr dalpha: the
// interior integrand separates into r^(1-m), integrated exactly, and
// S_m = int sin^2(alpha) P_m'(cos alpha) dalpha, a trigonometric polynomial of degree m + 1
// integrated by composite Gauss with panels short against its period.
std::vector<double> spherical_coil_interior_coefficients(const SphericalCoil& c, double current,
                                                         int n_terms) {
  const double area =
      0.5 * (c.r_outer * c.r_outer - c.r_inner * c.r_inner) * (c.alpha_max - c.alpha_min);
  const double j = current / area;
  std::vector<double> s(static_cast<std::size_t>(n_terms + 1), 0.0), p, dp;
  const int panels = 1 + static_cast<int>(std::ceil(n_terms * (c.alpha_max - c.alpha_min) / 4.0));
  for (const Node1& node : composite_rule(c.alpha_min, c.alpha_max, panels)) {
    legendre_with_derivative(std::cos(node.x), n_terms, p, dp);
    const double sin2 = std::sin(node.x) * std::sin(node.x);
    for (int m = 1; m <= n_terms; ++m) {
      s[static_cast<std::size_t>(m)] += node.w * sin2 * dp[static_cast<std::size_t>(m)];
    }
  }
  std::vector<double> coef(static_cast<std::size_t>(n_terms + 1), 0.0);
  const double x = c.r_outer / c.r_inner;
  for (int m = 1; m <= n_terms; ++m) {
    // r_inner^(m-1) int r^(1-m) dr
    const double radial =
        c.r_inner * (m == 2 ? std::log(x) : (std::pow(x, 2.0 - m) - 1.0) / (2.0 - m));
    coef[static_cast<std::size_t>(m)] = -j / (2.0 * m) * radial * s[static_cast<std::size_t>(m)];
  }
  return coef;
}

// A solenoid is a stack of current sheets of radius a (sheet current K = J da) between
// z1 = -L/2 and z2 = L/2, whose on-axis field (K/2)[g(z - z1) - g(z - z2)], g(u) = u/sqrt(a^2+u^2),
// expands about z = 0 through the generating function of P_n about each end
// (R_e = sqrt(a^2 + z_e^2), t_e = z_e / R_e):
//   c_m R^-(m-1) = -d_{m-1} / m, d_0 = K (t_2 - t_1) / 2,
//   d_n = K a^2 / (2n) [P_n'(t_1) / R_1^(n+2) - P_n'(t_2) / R_2^(n+2)],
// then integrated over a by composite Gauss (smooth in a; panels short against the variation
// of (R/R_e)^n and of the angle of each end). The series converges like (r / |z_e + i a|)^n,
// faster than the (r / r_inner)^n of its region of validity.
std::vector<double> solenoid_interior_coefficients(const Solenoid& c, double current, int n_terms) {
  const double j = current / ((c.r_outer - c.r_inner) * c.length);
  const double half = 0.5 * c.length;
  const double radius = c.r_inner;
  const double variation = std::log(std::hypot(c.r_outer, half) / std::hypot(c.r_inner, half)) +
                           std::abs(std::atan2(c.r_outer, half) - std::atan2(c.r_inner, half));
  const int panels = 1 + static_cast<int>(std::ceil(n_terms * variation / 4.0));
  std::vector<double> coef(static_cast<std::size_t>(n_terms + 1), 0.0), p, dp;
  for (const Node1& node : composite_rule(c.r_inner, c.r_outer, panels)) {
    const double a = node.x, k = j * node.w;
    for (const double sign : {-1.0, 1.0}) { // end z1 = -L/2, then z2 = +L/2
      const double ze = sign * half;
      const double re = std::hypot(a, ze), te = ze / re;
      legendre_with_derivative(te, n_terms, p, dp);
      coef[1] -= sign * k * te / 2.0;
      double ratio = 1.0; // (R / R_e)^n
      for (int m = 2; m <= n_terms; ++m) {
        const int n = m - 1;
        ratio *= radius / re;
        const double dn =
            -sign * k * a * a / (2.0 * n) * dp[static_cast<std::size_t>(n)] * ratio / (re * re);
        coef[static_cast<std::size_t>(m)] -= dn / m;
      }
    }
  }
  return coef;
}

} // namespace magfem
