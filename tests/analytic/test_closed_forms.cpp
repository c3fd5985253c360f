// Closed forms (analytic/closed_forms.hpp): Harwin's eqs. 3 and 4 against direct numerical
// integration of the line currents they come from, how eq. 3 differs from a uniformly
// magnetized cylinder, and the interface conditions of the uniform sphere and cylinder.
#include <cmath>
#include <cstdio>
#include <functional>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "analytic/closed_forms.hpp"
#include "analytic/legendre.hpp"

namespace magfem {
namespace {

// Adaptive Gauss-Legendre (10 vs 2 x 10 nodes) to an absolute tolerance (tesla here; the
// fields are 0.01..10 T, so 1e-13 T is far below the 1e-8 relative asserted).
double integrate(const std::function<double(double)>& f, double a, double b, double tol,
                 int depth = 0) {
  static const QuadratureRule rule = gauss_legendre(10);
  auto gl = [&](double lo, double hi) {
    double s = 0;
    for (std::size_t i = 0; i < rule.x.size(); ++i) {
      s += rule.w[i] * f(0.5 * (lo + hi) + 0.5 * (hi - lo) * rule.x[i]);
    }
    return 0.5 * (hi - lo) * s;
  };
  const double m = 0.5 * (a + b);
  const double whole = gl(a, b), halves = gl(a, m) + gl(m, b);
  if (std::abs(whole - halves) < tol || depth > 30) {
    return halves;
  }
  return integrate(f, a, m, 0.5 * tol, depth + 1) + integrate(f, m, b, 0.5 * tol, depth + 1);
}

// Radial B at (R, phi) of line currents on the circle of radius r: current per radian
// i(t) along +z at angle t, each the 2D field mu0 i dt / (2 pi) z x d / |d|^2 (Biot-Savart for
// an infinite line), summed as vectors and projected on e_R. `breaks` are angles where i(t)
// jumps, so that each piece is smooth.
double line_current_radial_B(const std::function<double(double)>& current, double r, double R,
                             double phi, std::vector<double> breaks) {
  const Eigen::Vector2d x(R * std::cos(phi), R * std::sin(phi));
  const Eigen::Vector2d e_R = x / R;
  auto integrand = [&](double t) {
    const Eigen::Vector2d d = x - Eigen::Vector2d(r * std::cos(t), r * std::sin(t));
    const Eigen::Vector2d z_cross_d(-d.y(), d.x());
    return mu0 * current(t) / (2 * pi) * z_cross_d.dot(e_R) / d.squaredNorm();
  };
  std::sort(breaks.begin(), breaks.end());
  double sum = 0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    sum += integrate(integrand, breaks[i], breaks[i + 1], 1e-13);
  }
  return sum;
}

constexpr double kI = 6.6e4;       // A/rad, the paper's Fig. 3 fit
constexpr double kRadius = 0.0115; // 23 mm diameter magnet

// Eq. 3: -I on |t| < pi/2 (x > 0), +I on the other half.
TEST(ClosedForms, HarwinEq3MatchesLineCurrentIntegration) {
  const HarwinCylinder c{kI, kRadius, 0.0};
  auto current = [](double t) { return std::cos(t) > 0 ? -kI : kI; };
  for (double ratio : {0.3, 0.8, 1.1, 1.5, 3.0}) {
    for (double phi : {0.0, 0.4, 1.2, pi / 2 - 0.05, 2.0, 3.5, 5.0}) {
      const double R = ratio * kRadius;
      const double ref =
          line_current_radial_B(current, kRadius, R, phi, {-pi / 2, pi / 2, 3 * pi / 2});
      const double b = harwin_eq3_radial_B(c, R, phi);
      EXPECT_NEAR(b, ref, 1e-8 * std::max(std::abs(ref), 1e-3))
          << "R/r=" << ratio << " phi=" << phi;
    }
  }
}

// Eq. 4: no current within Delta of the pole lines t = +-pi/2; finite on the surface there.
TEST(ClosedForms, HarwinEq4MatchesLineCurrentIntegration) {
  const double delta = 15 * deg_to_rad;
  const HarwinCylinder c{3.6e4, kRadius, delta};
  auto current = [&](double t) {
    const double d = std::min(std::abs(std::remainder(t - pi / 2, 2 * pi)),
                              std::abs(std::remainder(t + pi / 2, 2 * pi)));
    if (d < delta) {
      return 0.0;
    }
    return std::cos(t) > 0 ? -c.current_per_rad : c.current_per_rad;
  };
  const std::vector<double> breaks{-pi / 2 - delta, -pi / 2 + delta, pi / 2 - delta, pi / 2 + delta,
                                   3 * pi / 2 - delta};
  for (double ratio : {0.5, 1.0, 1.05, 2.0}) {
    for (double phi : {0.0, 0.7, pi / 2, 2.1, 4.0}) {
      if (ratio == 1.0 && std::abs(std::cos(phi)) > std::sin(delta)) {
        continue; // on the sheet itself B_r is finite but the integrand is singular
      }
      const double R = ratio * kRadius;
      const double ref = line_current_radial_B(current, kRadius, R, phi, breaks);
      const double b = harwin_eq4_radial_B(c, R, phi);
      EXPECT_NEAR(b, ref, 1e-8 * std::max(std::abs(ref), 1e-3))
          << "R/r=" << ratio << " phi=" << phi;
    }
  }
  // Without bands eq. 4 is eq. 3; the printed eq. 4 is -2 times the derived one.
  const HarwinCylinder no_band{3.6e4, kRadius, 0.0};
  for (double phi : {0.3, 1.0, 2.5}) {
    EXPECT_NEAR(harwin_eq4_radial_B(no_band, 0.02, phi), harwin_eq3_radial_B(no_band, 0.02, phi),
                1e-14);
    EXPECT_NEAR(harwin_eq4_as_printed_radial_B(c, 0.02, phi),
                -2 * harwin_eq4_radial_B(c, 0.02, phi), 1e-12);
  }
}

// Eq. 3's current is a square wave in angle: (4I/pi)(cos t - cos 3t/3 + cos 5t/5 - ...), so
// outside (R > r) its radial field is (2 mu0 I/(pi R)) sum_k odd (-1)^((k-1)/2) (r/R)^k
// sin(k phi)/k: odd harmonics 1/3, 1/5 of the fundamental, times (r/R)^(k-1). A uniformly
// magnetized cylinder (M along +y, current -M r cos t per radian along z) with the same
// fundamental, B_r = 4 mu0 I / (pi r), is a pure first harmonic. On the pole line their ratio is
// atanh(r/R) / (r/R), which diverges at the surface: the discrepancy the paper removes with
// eq. 4's bands.
TEST(ClosedForms, HarwinEq3VersusUniformCylinder) {
  const HarwinCylinder c{kI, kRadius, 0.0};
  const double B_r = 4 * mu0 * kI / (pi * kRadius);
  const Eigen::Vector2d remanence(0.0, B_r);
  auto uniform_radial = [&](double R, double phi) {
    const Eigen::Vector2d x(R * std::cos(phi), R * std::sin(phi));
    return uniform_cylinder_B(x, Eigen::Vector2d::Zero(), kRadius, remanence).dot(x / R);
  };
  const double R = 1.25 * kRadius, q = kRadius / R;
  const int n = 4096; // trapezoid on a periodic analytic function: spectrally accurate
  std::vector<double> b_eq3(8, 0.0), b_uni(8, 0.0), a_eq3(8, 0.0);
  for (int i = 0; i < n; ++i) {
    const double phi = 2 * pi * i / n;
    for (int k = 1; k < 8; ++k) {
      b_eq3[k] += 2.0 / n * harwin_eq3_radial_B(c, R, phi) * std::sin(k * phi);
      a_eq3[k] += 2.0 / n * harwin_eq3_radial_B(c, R, phi) * std::cos(k * phi);
      b_uni[k] += 2.0 / n * uniform_radial(R, phi) * std::sin(k * phi);
    }
  }
  const double b1 = 2 * mu0 * kI / (pi * R) * q;
  EXPECT_NEAR(b_eq3[1], b1, 1e-10 * b1);
  EXPECT_NEAR(b_uni[1], b1, 1e-10 * b1) << "matched fundamental";
  EXPECT_NEAR(b_eq3[3], -b1 * q * q / 3, 1e-10 * b1);
  EXPECT_NEAR(b_eq3[5], b1 * std::pow(q, 4) / 5, 1e-10 * b1);
  EXPECT_NEAR(b_eq3[7], -b1 * std::pow(q, 6) / 7, 1e-10 * b1);
  for (int k : {2, 3, 4, 5, 6, 7}) {
    EXPECT_NEAR(b_uni[k], 0.0, 1e-12 * b1) << "uniform cylinder is a pure first harmonic";
  }
  for (int k = 1; k < 8; ++k) {
    EXPECT_NEAR(a_eq3[k], 0.0, 1e-12 * b1);
    if (k % 2 == 0) {
      EXPECT_NEAR(b_eq3[k], 0.0, 1e-12 * b1);
    }
  }
  for (double ratio : {1.02, 1.05, 1.2, 2.0}) {
    const double Rk = ratio * kRadius, qk = 1 / ratio;
    const double pole = harwin_eq3_radial_B(c, Rk, pi / 2) / uniform_radial(Rk, pi / 2);
    EXPECT_NEAR(pole, std::atanh(qk) / qk, 1e-12);
    std::printf("R/r = %.2f: pole-line B_r eq.3 / uniform cylinder (same fundamental) = %.3f\n",
                ratio, pole);
  }
}

// Uniform sphere: normal B continuous and tangential H jumping by M_t across the surface;
// shell: zero field in the cavity. Uniform cylinder: the same conditions in 2D.
TEST(ClosedForms, UniformSphereAndCylinderInterfaceConditions) {
  const Eigen::Vector3d c(0.01, -0.02, 0.03), Br(0.4, -0.9, 0.6);
  const double a = 0.02, eps = 1e-9;
  for (const Eigen::Vector3d& n : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 2, 3).normalized(),
                                   Eigen::Vector3d(0, 0, -1)}) {
    const Eigen::Vector3d bi = uniform_sphere_B(c + (a - eps) * n, c, a, Br);
    const Eigen::Vector3d bo = uniform_sphere_B(c + (a + eps) * n, c, a, Br);
    EXPECT_NEAR(bi.dot(n), bo.dot(n), 1e-7);
    // H = B/mu0 - M inside, B/mu0 outside: tangential (B_in - Br) = B_out, tangential part.
    const Eigen::Vector3d jump = (bi - Br) - bo;
    EXPECT_LT((jump - jump.dot(n) * n).norm(), 1e-7);
  }
  EXPECT_LT(uniform_shell_B(c + Eigen::Vector3d(0.005, 0, 0), c, 0.01, a, Br).norm(), 1e-15);
  const Eigen::Vector2d c2(0.0, 0.0), Br2(0.3, 1.0);
  for (double t : {0.0, 1.0, 2.5, 4.0}) {
    const Eigen::Vector2d n(std::cos(t), std::sin(t));
    const Eigen::Vector2d bi = uniform_cylinder_B((a - eps) * n, c2, a, Br2);
    const Eigen::Vector2d bo = uniform_cylinder_B((a + eps) * n, c2, a, Br2);
    EXPECT_NEAR(bi.dot(n), bo.dot(n), 1e-7);
    const Eigen::Vector2d tang(-n.y(), n.x());
    EXPECT_NEAR((bi - Br2).dot(tang), bo.dot(tang), 1e-7);
  }
  // Issue 2's example: M along x, B_r = 1 T, a = 10 mm: at r = 12 mm, phi = 0 B_r = 0.5 (10/12)^2.
  const Eigen::Vector2d b12 = uniform_cylinder_B({0.012, 0.0}, c2, 0.010, {1.0, 0.0});
  EXPECT_NEAR(b12.x(), 0.5 * std::pow(10.0 / 12.0, 2), 1e-15);
}

} // namespace
} // namespace magfem
