// Closed forms for coaxial coils (analytic/coil_closed_forms.hpp) against published tables
// and against each other: Nagaoka's coefficients, the Brooks coil, Wheeler's approximation,
// the current sheet as the thin limit of the thick coil, the on-axis field against direct
// integration of the loops, and mutual inductance and force (finite difference, action and
// reaction, dipole limit).
#include <cmath>
#include <initializer_list>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "core/gauss_legendre.hpp"
#include "analytic/coil_closed_forms.hpp"

namespace magfem {
namespace {

// Nagaoka's table (H. Nagaoka, J. Coll. Sci. Tokyo 27, 1909; reproduced in F. W. Grover,
// "Inductance Calculations", 1946, and in every handbook since) to its 4 decimals: K_N against
// diameter / length.
TEST(CoilClosedForms, NagaokaCoefficientsMatchTheTable) {
  const double table[][2] = {
      {0.1, 0.9588}, {0.5, 0.8181}, {1.0, 0.6884}, {2.0, 0.5255}, {10.0, 0.2033}};
  for (const auto& row : table) {
    const double a = 0.05, length = 2 * a / row[0];
    EXPECT_NEAR(nagaoka_coefficient(a, length), row[1], 0.5e-4) << row[0];
  }
}

TEST(CoilClosedForms, CurrentSheetIntegralEqualsLorenzsClosedForm) {
  for (const double ratio : {0.1, 1.0, 10.0}) { // diameter / length
    const double a = 0.05, length = 2 * a / ratio;
    const double numeric = coaxial_coil_self_inductance(CoaxialCoil{a, a, 0, length, 100});
    const double closed = current_sheet_self_inductance(a, length, 100);
    // Two exact routes; the numerical one converges to 1e-15 (order 16 vs 32).
    EXPECT_NEAR(numeric, closed, 1e-12 * closed) << ratio;
  }
}

// The Brooks coil (square cross-section c x c, inner radius c, so mean radius a = 3c/2): the
// maximum inductance for a given length of wire, L = 1.6994e-6 a N^2 H with a in metres
// (Brooks 1931; Grover 1946, ch. 16), quoted to 5 digits.
TEST(CoilClosedForms, BrooksCoilMatchesGrover) {
  const double c = 0.02, n = 100;
  const double l = coaxial_coil_self_inductance(CoaxialCoil{c, 2 * c, 0, c, n});
  EXPECT_NEAR(l / (1.5 * c * n * n), 1.6994e-6, 0.00005e-6);
  // Converged: order 16 (default) against 24.
  EXPECT_NEAR(l, coaxial_coil_self_inductance(CoaxialCoil{c, 2 * c, 0, c, n}, 24), 1e-12 * l);
  // Wheeler's multilayer formula L = 0.8 a^2 N^2 / (6a + 9l + 10c) microhenry (inches),
  // stated accurate to about 1 % when the three terms are comparable, as here.
  const double inch = 0.0254, a = 1.5 * c / inch, len = c / inch, w = c / inch;
  const double wheeler = 0.8e-6 * a * a * n * n / (6 * a + 9 * len + 10 * w);
  EXPECT_NEAR(l, wheeler, 0.01 * l);
}

// As the winding thins the thick coil tends to the current sheet at its mean radius, the
// difference falling linearly with the width (the turns link areas differing by O(w a)).
TEST(CoilClosedForms, ThickCoilTendsToTheCurrentSheet) {
  const double a = 0.05, length = 0.1, n = 100;
  const double sheet = current_sheet_self_inductance(a, length, n);
  auto diff = [&](double w) {
    return coaxial_coil_self_inductance(CoaxialCoil{a - w / 2, a + w / 2, 0, length, n}) - sheet;
  };
  const double d1 = diff(1e-3), d2 = diff(1e-4);
  EXPECT_LT(d1, 0.0);
  EXPECT_NEAR(d2 / d1, 0.1, 0.005);
  EXPECT_LT(std::abs(d2), 2e-3 * sheet);
}

TEST(CoilClosedForms, AxialFieldMatchesIntegratedLoops) {
  // Sum over the cross-section of the loops' on-axis fields I a^2 / (2 (a^2 + u^2)^{3/2}),
  // 40 x 40 Gauss points (smooth: the axis is 1 cm from the winding).
  const CoaxialCoil c{0.01, 0.02, -0.03, 0.01, 250};
  const double current = 1.2;
  const QuadratureRule ga = gauss_legendre(40, c.r_inner, c.r_outer);
  const QuadratureRule gz = gauss_legendre(40, c.z_min, c.z_max);
  const double j = c.turns * current / ((c.r_outer - c.r_inner) * (c.z_max - c.z_min));
  for (const double z : {-0.05, -0.01, 0.0, 0.02, 0.3}) {
    double h = 0;
    for (std::size_t i = 0; i < ga.x.size(); ++i) {
      for (std::size_t k = 0; k < gz.x.size(); ++k) {
        const double a = ga.x[i], u = z - gz.x[k];
        h += ga.w[i] * gz.w[k] * j * a * a / (2 * std::pow(a * a + u * u, 1.5));
      }
    }
    EXPECT_NEAR(coaxial_coil_axial_H(c, current, z), h, 1e-12 * h) << z;
  }
  // A sheet: (K/2)(cos - cos) at the centre.
  const CoaxialCoil sheet{0.03, 0.03, -0.04, 0.04, 80};
  EXPECT_NEAR(coaxial_coil_axial_H(sheet, 2.0, 0.0),
              80 * 2.0 / 0.08 * 0.04 / std::hypot(0.03, 0.04), 1e-12);
}

TEST(CoilClosedForms, MutualInductanceAndAxialForce) {
  const CoaxialCoil a{0.01, 0.02, -0.01, 0.01, 100}, b{0.012, 0.025, 0.02, 0.03, 50};
  const double m = coaxial_mutual_inductance(a, b);
  EXPECT_NEAR(coaxial_mutual_inductance(b, a), m, 1e-12 * m);
  const double f = coaxial_axial_force(a, b, 2.0, 3.0);
  EXPECT_LT(f, 0.0); // like currents attract
  EXPECT_NEAR(coaxial_axial_force(b, a, 3.0, 2.0), -f, 1e-12 * std::abs(f));
  // F = I_a I_b dM/dz_b by central difference (h^2 truncation ~1e-10, round-off ~1e-10).
  const double h = 1e-6;
  CoaxialCoil up = b, down = b;
  up.z_min += h, up.z_max += h, down.z_min -= h, down.z_max -= h;
  const double fd =
      6.0 * (coaxial_mutual_inductance(a, up) - coaxial_mutual_inductance(a, down)) / (2 * h);
  EXPECT_NEAR(f, fd, 1e-7 * std::abs(f));
  // Far apart: dipoles m = N (mean enclosed area) on a common axis,
  // M = mu0 m_a m_b / (2 pi d^3), the next term (size / d)^2 ~ 1e-5 at d = 10 m.
  const double d = 10.0;
  const CoaxialCoil far{b.r_inner, b.r_outer, b.z_min + d, b.z_max + d, b.turns};
  auto moment = [](const CoaxialCoil& c) {
    return c.turns * pi * (std::pow(c.r_outer, 3) - std::pow(c.r_inner, 3)) /
           (3 * (c.r_outer - c.r_inner));
  };
  const double dist = 0.5 * (far.z_min + far.z_max) - 0.5 * (a.z_min + a.z_max);
  const double dipole = mu0 * moment(a) * moment(far) / (2 * pi * std::pow(dist, 3));
  EXPECT_NEAR(coaxial_mutual_inductance(a, far), dipole, 1e-4 * dipole);
  EXPECT_THROW(coaxial_mutual_inductance(a, CoaxialCoil{0.015, 0.03, 0.0, 0.02, 1}),
               std::invalid_argument);
}

} // namespace
} // namespace magfem
