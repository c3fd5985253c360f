#include "sources/loop_field.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "core/constants.hpp"

namespace magfem {

namespace {

// Below this parameter m the power series are used: they converge like m^n (16 terms reach
// 0.05^16 ~ 1e-21) and avoid the cancellations of the closed forms, whose brackets vanish
// like m^2 while their terms are O(1).
constexpr double m_series = 0.05;
constexpr int n_series = 16;

// Maclaurin coefficients in m, without the common factor pi/2:
//   K = sum c_n m^n, E = sum e_n m^n, c_n = ((2n-1)!! / (2n)!!)^2, e_n = c_n / (1 - 2n);
//   g = [E (1 - m/2) - K (1 - m)] / m^2 = sum gs_n m^n      (the loop's radial field);
//   f = [(2 - m) K - 2 E] / k = k sum fs_n m^n              (Maxwell's mutual inductance),
//   so f'(k) = sum (2n + 1) fs_n m^n.
struct Series {
  std::array<double, n_series> c{}, e{}, gs{}, fs{};
};

const Series& series() {
  static const Series s = [] {
    Series r;
    std::array<double, n_series + 3> c{}, e{};
    c[0] = 1.0;
    for (std::size_t n = 1; n < c.size(); ++n) {
      const double ratio = (2.0 * n - 1.0) / (2.0 * n);
      c[n] = c[n - 1] * ratio * ratio;
    }
    for (std::size_t n = 0; n < c.size(); ++n) {
      e[n] = c[n] / (1.0 - 2.0 * n);
    }
    for (std::size_t n = 0; n < static_cast<std::size_t>(n_series); ++n) {
      r.c[n] = c[n];
      r.e[n] = e[n];
      const std::size_t k = n + 2; // g's m^n comes from the brackets' m^(n+2)
      r.gs[n] = e[k] - 0.5 * e[k - 1] - c[k] + c[k - 1];
      // (2 - m) K - 2 E = sum [2 c_j - c_{j-1} - 2 e_j] m^j; j = n + 1 gives f's k m^n.
      const std::size_t j = n + 1;
      r.fs[n] = 2.0 * c[j] - c[j - 1] - 2.0 * e[j];
    }
    return r;
  }();
  return s;
}

double horner(const std::array<double, n_series>& a, double m) {
  double s = 0;
  for (int i = n_series - 1; i >= 0; --i) {
    s = s * m + a[static_cast<std::size_t>(i)];
  }
  return s;
}

} // namespace

CompleteElliptic complete_elliptic(double m, double kc) {
  // AGM: a_{n+1} = (a_n + b_n)/2, b_{n+1} = sqrt(a_n b_n), c_{n+1} = (a_n - b_n)/2;
  // K = pi / (2 a_inf), E = K (1 - sum_n 2^(n-1) c_n^2) with c_0^2 = m. Quadratic convergence:
  // once c < 1e-9 a the next c is below 1e-18 a and every later term is negligible.
  double a = 1.0, b = kc, p = 0.5, s = 0.5 * m;
  for (int it = 0; it < 40; ++it) {
    const double c = 0.5 * (a - b);
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
    p *= 2.0;
    s += p * c * c;
    if (c <= 1e-9 * a) {
      break;
    }
  }
  const double K = 0.5 * pi / a;
  return {K, K * (1.0 - s)};
}

MeridianField loop_field(double a, double z0, double current, double rho, double z) {
  if (a <= 0) {
    return {};
  }
  const double dz = z - z0;
  const double ap = a + rho, am = a - rho;
  const double beta2 = ap * ap + dz * dz, alpha2 = am * am + dz * dz;
  if (!(alpha2 > 0)) {
    return {};
  }
  const double beta = std::sqrt(beta2);
  const double m = 4.0 * a * rho / beta2;
  double K, E, g;
  if (m < m_series) {
    const Series& s = series();
    K = 0.5 * pi * horner(s.c, m);
    E = 0.5 * pi * horner(s.e, m);
    g = 0.5 * pi * horner(s.gs, m);
  } else {
    const double kc2 = alpha2 / beta2;
    const CompleteElliptic ke = complete_elliptic(m, std::sqrt(kc2));
    K = ke.K;
    E = ke.E;
    g = (E * (1.0 - 0.5 * m) - K * kc2) / (m * m);
  }
  // H_z = I / (2 pi beta) [K + (a^2 - rho^2 - dz^2) E / alpha^2];
  // H_rho = I dz / (2 pi rho beta) [E (a^2 + rho^2 + dz^2) / alpha^2 - K], whose bracket is
  // m^2 g / (1 - m): written with g it has no 1/rho and no cancellation near the axis.
  MeridianField h;
  h.h_z = current / (2.0 * pi * beta) * (K + (a * a - rho * rho - dz * dz) * E / alpha2);
  h.h_rho = 2.0 * current * a * dz * m * g / (pi * beta * alpha2);
  return h;
}

namespace {

// f(k) = [(2 - m) K - 2 E] / k and f'(k) = [(2 - m) E / kc^2 - 2 K] / m, m = k^2.
struct MaxwellF {
  double f, df;
};
MaxwellF maxwell_f(double m, double kc2) {
  const double k = std::sqrt(m);
  if (m < m_series) {
    const Series& s = series();
    double f = 0, df = 0;
    for (int i = n_series - 1; i >= 0; --i) {
      f = f * m + s.fs[static_cast<std::size_t>(i)];
      df = df * m + (2.0 * i + 1.0) * s.fs[static_cast<std::size_t>(i)];
    }
    return {0.5 * pi * k * f, 0.5 * pi * df};
  }
  const CompleteElliptic ke = complete_elliptic(m, std::sqrt(kc2));
  return {((2.0 - m) * ke.K - 2.0 * ke.E) / k, ((2.0 - m) * ke.E / kc2 - 2.0 * ke.K) / m};
}

} // namespace

double loop_mutual_inductance(double a1, double a2, double d) {
  const double s2 = (a1 + a2) * (a1 + a2) + d * d;
  const double kc2 = ((a1 - a2) * (a1 - a2) + d * d) / s2;
  if (!(kc2 > 0)) {
    return std::numeric_limits<double>::infinity();
  }
  const double m = 4.0 * a1 * a2 / s2;
  return mu0 * std::sqrt(a1 * a2) * maxwell_f(m, kc2).f;
}

double loop_mutual_inductance_dd(double a1, double a2, double d) {
  const double s2 = (a1 + a2) * (a1 + a2) + d * d;
  const double kc2 = ((a1 - a2) * (a1 - a2) + d * d) / s2;
  if (!(kc2 > 0)) {
    return 0.0;
  }
  const double m = 4.0 * a1 * a2 / s2;
  const double k = std::sqrt(m);
  // dk/dd = -k d / ((a1 + a2)^2 + d^2).
  return mu0 * std::sqrt(a1 * a2) * maxwell_f(m, kc2).df * (-k * d / s2);
}

} // namespace magfem
