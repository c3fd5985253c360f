// The filament loop (sources/loop_field.hpp): field against the Biot-Savart line integral and
// the on-axis formula, elliptic integrals against the standard library, Maxwell's mutual
// inductance against Neumann's double line integral, and its derivative against both a finite
// difference and the force of the loop field on the other loop.
#include <cmath>
#include <initializer_list>
#include <random>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "sources/loop_field.hpp"

namespace magfem {
namespace {

// Biot-Savart line integral of a loop (radius a, plane z0, current I) at (rho, 0, z) by the
// trapezoid rule, spectrally accurate for the periodic integrand: with n nodes the error falls
// like exp(-n eta), eta ~ (distance to the wire) / a.
MeridianField biot_savart_loop(double a, double z0, double current, double rho, double z, int n) {
  MeridianField h;
  for (int k = 0; k < n; ++k) {
    const double phi = 2 * pi * k / n, c = std::cos(phi), s = std::sin(phi);
    const double rx = rho - a * c, ry = -a * s, rz = z - z0;
    const double r3 = std::pow(rx * rx + ry * ry + rz * rz, 1.5);
    // dl = a (-s, c, 0) dphi; (dl x r)_x = c rz a, (dl x r)_z = a (-s ry - c rx)
    h.h_rho += current / (4 * pi) * a * c * rz / r3 * (2 * pi / n);
    h.h_z += current / (4 * pi) * a * (-s * ry - c * rx) / r3 * (2 * pi / n);
  }
  return h;
}

TEST(LoopField, MatchesTheBiotSavartLineIntegral) {
  std::mt19937 gen(1);
  std::uniform_real_distribution<double> u(0, 1);
  const double a = 0.03, current = 2.5;
  for (int t = 0; t < 400; ++t) {
    // Points from next to the wire (1 % of a) to 10 a, near the axis and far along it.
    double rho = a * std::pow(10.0, -6 + 7 * u(gen)), z = a * (20 * u(gen) - 10);
    if (t % 2 == 0) {
      const double d = a * std::pow(10.0, -2 + 2 * u(gen)), th = 2 * pi * u(gen);
      rho = a + d * std::cos(th);
      z = d * std::sin(th);
    }
    const MeridianField h = loop_field(a, 0.0, current, rho, z);
    const MeridianField ref = biot_savart_loop(a, 0.0, current, rho, z, 20000);
    // Both exact; the reference's trapezoid error at 1 % of a is exp(-200).
    EXPECT_NEAR(h.h_rho, ref.h_rho, 1e-11 * std::hypot(ref.h_rho, ref.h_z)) << rho << " " << z;
    EXPECT_NEAR(h.h_z, ref.h_z, 1e-11 * std::hypot(ref.h_rho, ref.h_z)) << rho << " " << z;
  }
}

TEST(LoopField, OnAndNearTheAxis) {
  const double a = 0.02, z0 = 0.01, current = 3.0;
  for (const double dz : {-0.1, -0.02, 0.0, 0.005, 0.3}) {
    const MeridianField h = loop_field(a, z0, current, 0.0, z0 + dz);
    const double s = a * a + dz * dz;
    EXPECT_EQ(h.h_rho, 0.0);
    EXPECT_NEAR(h.h_z, current * a * a / (2 * std::pow(s, 1.5)), 1e-13 * h.h_z);
    // Near the axis H_rho = -(rho/2) dH_z/dz = (3/4) I a^2 rho dz / s^{5/2} + O(rho^3): the
    // closed form would lose all digits to cancellation here; the series form keeps them.
    const double rho = 1e-9 * a;
    const MeridianField n = loop_field(a, z0, current, rho, z0 + dz);
    EXPECT_NEAR(n.h_rho, 0.75 * current * a * a * rho * dz / std::pow(s, 2.5),
                1e-12 * current / a * rho / a);
  }
}

TEST(LoopField, CompleteEllipticIntegralsMatchTheStandardLibrary) {
  for (const double m : {0.0, 1e-10, 0.01, 0.3, 0.7, 0.99, 0.999999}) {
    const double k = std::sqrt(m);
    const CompleteElliptic ke = complete_elliptic(m, std::sqrt(1 - m));
    // Both to round-off; 1 - m itself carries the relative error 1e-16 / (1 - m).
    EXPECT_NEAR(ke.K, std::comp_ellint_1(k), 1e-14 * ke.K / (1 - m));
    EXPECT_NEAR(ke.E, std::comp_ellint_2(k), 1e-14 * ke.E / (1 - m));
  }
}

// Neumann: M = mu0 / (4 pi) oint oint dl1 . dl2 / |r1 - r2|, trapezoid in both angles (the
// integrand depends on the angle difference only, so one sum suffices). Summed in long double
// on an exactly periodic grid: far apart, the terms cancel to a fraction (a / d)^2 of their
// size.
double neumann(double a1, double a2, double d, int n) {
  const long double pi_l = 3.141592653589793238462643383279502884L;
  long double s = 0;
  for (int k = 0; k < n; ++k) {
    const long double psi = 2 * pi_l * k / n;
    s += a1 * a2 * std::cos(psi) /
         std::sqrt(a1 * a1 + a2 * a2 - 2 * a1 * a2 * std::cos(psi) +
                   static_cast<long double>(d) * d);
  }
  return mu0 / (4 * pi) * 2 * pi * static_cast<double>(s) * (2 * pi / n);
}

TEST(MutualInductance, MatchesNeumannsDoubleLineIntegral) {
  for (const double d : {0.0, 0.002, 0.01, 0.05, 0.2, 1.0, 10.0}) {
    const double a1 = 0.05, a2 = 0.03;
    // Loops 0.02 apart at least: trapezoid error exp(-n 0.02 / 0.05) with n = 4000.
    EXPECT_NEAR(loop_mutual_inductance(a1, a2, d), neumann(a1, a2, d, 4000),
                1e-12 * neumann(a1, a2, d, 4000))
        << d;
  }
  EXPECT_EQ(loop_mutual_inductance(0.03, 0.05, 0.1), loop_mutual_inductance(0.05, 0.03, 0.1));
  EXPECT_EQ(loop_mutual_inductance(0.03, 0.05, 0.1), loop_mutual_inductance(0.03, 0.05, -0.1));
}

TEST(MutualInductance, DerivativeIsTheForceOfOneLoopsFieldOnTheOther) {
  for (const double d : {-0.3, -0.01, 0.0, 1e-4, 0.02, 0.1, 2.0}) {
    const double a1 = 0.04, a2 = 0.025;
    const double dm = loop_mutual_inductance_dd(a1, a2, d);
    // F_z on loop 2 = I2 oint (dl x B1)_z = -2 pi a2 I2 mu0 H_rho(loop 1 at a2, d): the
    // loop field's path, independent of the derivative of Maxwell's formula.
    const double force = -2 * pi * a2 * mu0 * loop_field(a1, 0.0, 1.0, a2, d).h_rho;
    EXPECT_NEAR(dm, force, 1e-12 * std::abs(force) + 1e-22) << d;
    // Central difference, h^2 truncation and 1e-16 M / h round-off, both ~1e-9 relative.
    const double h = 1e-5 * (std::abs(d) + a2);
    const double fd =
        (loop_mutual_inductance(a1, a2, d + h) - loop_mutual_inductance(a1, a2, d - h)) / (2 * h);
    EXPECT_NEAR(dm, fd, 1e-7 * std::abs(loop_mutual_inductance(a1, a2, d)) / a2) << d;
    // Action = reaction: the force on loop 1 (at -d from loop 2) is opposite.
    EXPECT_EQ(loop_mutual_inductance_dd(a2, a1, -d), -dm);
  }
  EXPECT_LT(loop_mutual_inductance_dd(0.04, 0.025, 0.01), 0.0); // like currents attract
}

} // namespace
} // namespace magfem
