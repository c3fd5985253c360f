// Harmonic-form interaction of concentric axisymmetric magnets (validation/
// axisymmetric_interaction.hpp) against a closed form and against the charge interaction
// (an independent method: surface and volume charges integrated by adaptive cubature).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "analytic/analytic_force.hpp"
#include "analytic/axisymmetric_interaction.hpp"

namespace magfem {
namespace {

using Vec3 = Eigen::Vector3d;

AnalyticMagnet segment(double r1, double r2, double t1, double t2, bool radial, double sign,
                       double gamma_about_y) {
  AnalyticMagnet m;
  m.shape = SphericalSegment{r1, r2, t1, t2, 0, 2 * pi};
  m.B_r = 1.3;
  m.magnetization.pattern =
      radial ? Magnetization::Pattern::radial : Magnetization::Pattern::parallel;
  m.magnetization.sign = sign;
  m.placement = Placement{}.rotated(Vec3::UnitY(), gamma_about_y, Vec3::Zero());
  m.magnetization = m.magnetization.rotated(m.placement.rotation, Vec3::Zero());
  return m;
}

// Table 4.2 compensator (thesis ch. 4): inner solid hemisphere 29 mm parallel +z, outer
// hemispherical shell 30..43 mm radial inwards, outer rotated by gamma about y.
AnalyticMagnet inner42() {
  auto m = segment(0, 0.029, 0, pi / 2, false, 1, 0);
  m.name = "inner";
  return m;
}
AnalyticMagnet outer42(double gamma) {
  auto m = segment(0.030, 0.043, 0, pi / 2, true, -1, gamma);
  m.name = "outer";
  return m;
}

TEST(AxisymmetricInteraction, DipoleSphereInRadialHemisphericalShellClosedForm) {
  // A uniformly magnetized sphere acts as the point dipole m = 4/3 pi a^3 M (its only
  // non-zero interior moment is n = 1), so T = mu0 m x H_B(0). At the centre of a radial
  // hemispherical shell r1..r2 (charges sigma = +-M at r2/r1, rho = -2M/r) the field is
  // H_B(0) = (M/2) ln(r2/r1) along its axis. Exact up to round-off.
  const double a = 0.02, r1 = 0.025, r2 = 0.04, M = 1.3 / mu0;
  for (double gamma_deg : {0.0, 30.0, 90.0, 135.0}) {
    const auto sphere = segment(0, a, 0, pi, false, 1, 0);
    const auto shell = segment(r1, r2, 0, pi / 2, true, 1, gamma_deg * deg_to_rad);
    const auto r = axisymmetric_interaction({sphere}, {shell});
    const Vec3 m = 4.0 / 3.0 * pi * a * a * a * M * Vec3::UnitZ();
    const Vec3 h = 0.5 * M * std::log(r2 / r1) * shell.placement.rotation.col(2);
    const Vec3 expected = mu0 * m.cross(h);
    EXPECT_LT((r.torque - expected).norm(), 1e-12 * mu0 * m.norm() * h.norm()) << gamma_deg;
    EXPECT_NEAR(r.energy, -mu0 * m.dot(h), 1e-12 * mu0 * m.norm() * h.norm());
    // Newton's third law: the reaction on the shell.
    const auto back = axisymmetric_interaction({shell}, {sphere});
    EXPECT_LT((back.torque + r.torque).norm(), 1e-12 * mu0 * m.norm() * h.norm());
  }
}

TEST(AxisymmetricInteraction, TruncationBoundHolds) {
  // The printed bound must cover the difference to a much longer series.
  AxisymmetricInteractionOptions loose, tight;
  loose.tolerance = 1e-5;
  tight.tolerance = 1e-14;
  for (double gamma_deg : {20.0, 90.0}) {
    const auto a = axisymmetric_interaction({inner42()}, {outer42(gamma_deg * deg_to_rad)}, loose);
    const auto b = axisymmetric_interaction({inner42()}, {outer42(gamma_deg * deg_to_rad)}, tight);
    EXPECT_GT(b.n_max, a.n_max);
    EXPECT_LE((a.torque - b.torque).norm(), a.torque_bound + b.torque_bound) << gamma_deg;
    EXPECT_LE((a.force - b.force).norm(), a.force_bound + b.force_bound) << gamma_deg;
    RecordProperty("n_max_1e-5_" + std::to_string(int(gamma_deg)), a.n_max);
    RecordProperty("n_max_1e-14_" + std::to_string(int(gamma_deg)), b.n_max);
  }
}

TEST(AxisymmetricInteraction, CompensatorCurveIsFastAndConverged) {
  // 19 angles 0..180 deg in <= 0.1 s (issue 14), truncation bound <= 1e-6 of the peak.
  const auto t0 = std::chrono::steady_clock::now();
  double peak = 0, worst_bound = 0;
  int n_max = 0;
  for (int i = 0; i <= 18; ++i) {
    const auto r = axisymmetric_interaction({inner42()}, {outer42(i * 10 * deg_to_rad)});
    peak = std::max(peak, r.torque.norm());
    worst_bound = std::max(worst_bound, r.torque_bound);
    n_max = r.n_max;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(worst_bound, 1e-6 * peak);
  EXPECT_NEAR(peak, 12.3653, 1e-4); // the charge interaction's converged peak, at 90 deg
  RecordProperty("seconds_19_angles", std::to_string(seconds));
  RecordProperty("n_max", n_max);
  RecordProperty("torque_bound_over_peak", std::to_string(worst_bound / peak));
}

// The charge interaction at its default tolerance (1e-6 of the sum of |contributions|) against
// the harmonic form (truncation bound 1e-10 of its scale). The tolerance is an error-per-box
// criterion, so the charge result is typically far better than 1e-6: measured 1.2e-9 (60 deg)
// and 1.4e-9 (90 deg) of the peak torque 12.37 Nm, 2.8e-9 of the peak force 536.3 N. 1e-7 of
// the peaks leaves room for other compilers and still checks the 1e-6.
void compare_with_charge(double gamma_deg) {
  const auto h = axisymmetric_interaction({inner42()}, {outer42(gamma_deg * deg_to_rad)});
  const auto c = charge_interaction({inner42()}, {outer42(gamma_deg * deg_to_rad)}, Vec3::Zero());
  EXPECT_LT((h.torque - c.torque).norm(), 1e-7 * 12.37)
      << h.torque.transpose() << " vs " << c.torque.transpose();
  EXPECT_LT((h.force - c.force).norm(), 1e-7 * 536.3)
      << h.force.transpose() << " vs " << c.force.transpose();
  char text[160];
  std::snprintf(text, sizeof text,
                "T %.9g vs %.9g, |dT|/12.37 %.2g; F %.9g vs %.9g, |dF|/536.3 %.2g", h.torque.y(),
                c.torque.y(), (h.torque - c.torque).norm() / 12.37, h.force.z(), c.force.z(),
                (h.force - c.force).norm() / 536.3);
  std::printf("%g deg: %s\n", gamma_deg, text);
  ::testing::Test::RecordProperty("comparison", text);
}

TEST(AxisymmetricInteraction, CompensatorEqualsChargeInteractionAt60Degrees) {
  compare_with_charge(60);
}

TEST(AxisymmetricInteraction, CompensatorEqualsChargeInteractionAt90Degrees) {
  compare_with_charge(90);
}

TEST(AxisymmetricInteraction, RefusesWhatItDoesNotCover) {
  auto off_centre = inner42();
  off_centre.placement.translation = Vec3(0, 0, 0.001);
  EXPECT_THROW(axisymmetric_interaction({off_centre}, {outer42(0)}), std::invalid_argument);
  auto quarter = outer42(0);
  std::get<SphericalSegment>(quarter.shape).phi_max = pi / 2;
  EXPECT_THROW(axisymmetric_interaction({inner42()}, {quarter}), std::invalid_argument);
  auto tilted = inner42();
  tilted.magnetization.direction = Vec3::UnitX();
  EXPECT_THROW(axisymmetric_interaction({tilted}, {outer42(0)}), std::invalid_argument);
  auto overlapping = outer42(0);
  std::get<SphericalSegment>(overlapping.shape).r_inner = 0.028;
  EXPECT_THROW(axisymmetric_interaction({inner42()}, {overlapping}), std::invalid_argument);
}

} // namespace
} // namespace magfem
