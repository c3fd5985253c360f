// Force and torque from analytic fields: uniformly magnetized spheres act exactly as point
// dipoles (outside field and, by the mean-value property of harmonic fields, force and
// torque in an external field), so charge interaction and Maxwell stress must reproduce the
// dipole formulas.
#include <cmath>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "uniform_balls.hpp"
#include "analytic/analytic_force.hpp"
#include "analytic/charge_model.hpp"

namespace magfem {
namespace {

using Vec3 = Eigen::Vector3d;
using test::ball;
using test::moment;

Vec3 dipole_B(const Vec3& m, const Vec3& r) {
  const double n = r.norm();
  const Vec3 u = r / n;
  return mu0 / (4 * pi * n * n * n) * (3 * u * u.dot(m) - m);
}

// Force on dipole m2 at r2 from dipole m1 at r1.
Vec3 dipole_force(const Vec3& m1, const Vec3& m2, const Vec3& r) {
  const double n = r.norm();
  const Vec3 u = r / n;
  return 3 * mu0 / (4 * pi * std::pow(n, 4)) *
         (m1.dot(u) * m2 + m2.dot(u) * m1 + m1.dot(m2) * u - 5 * m1.dot(u) * m2.dot(u) * u);
}

struct Pair {
  Vec3 c1{0, 0, 0}, c2{0.012, -0.004, 0.009};
  double a1 = 0.005, a2 = 0.004;
  Vec3 d1{0.2, 0.3, 1.0}, d2{-0.5, 1.0, 0.3};
  double B1 = 1.3, B2 = 1.0;
};

// The charge-interaction integral uses adaptive quadrature to `tolerance` relative to the
// sum of contribution magnitudes; 1e-6 of the exact force is what the issue asks for.
constexpr double force_tol = 1e-6;

TEST(ChargeForce, TwoSpheresChargeInteractionIsDipoleForce) {
  const Pair p;
  const Vec3 m1 = moment(p.a1, p.d1, p.B1), m2 = moment(p.a2, p.d2, p.B2);
  const Vec3 exact_f = dipole_force(m1, m2, p.c2 - p.c1);
  // Torque about sphere 2's centre: m2 x B1(c2).
  const Vec3 exact_t = m2.cross(dipole_B(m1, p.c2 - p.c1));
  ChargeInteractionOptions opt;
  opt.tolerance = 1e-8;
  opt.field.tolerance = 1e-8;
  const ForceTorque ft =
      charge_interaction({ball(p.c2, p.a2, p.d2, p.B2)}, {ball(p.c1, p.a1, p.d1, p.B1)}, p.c2, opt);
  EXPECT_LT((ft.force - exact_f).norm(), force_tol * exact_f.norm())
      << ft.force.transpose() << " vs " << exact_f.transpose();
  EXPECT_LT((ft.torque - exact_t).norm(), force_tol * exact_t.norm())
      << ft.torque.transpose() << " vs " << exact_t.transpose();
}

TEST(ChargeForce, TwoSpheresMaxwellStressIsDipoleForce) {
  // Stress sphere around magnet 2 cutting through air only (radius between a2 and the gap).
  const Pair p;
  const Vec3 m1 = moment(p.a1, p.d1, p.B1), m2 = moment(p.a2, p.d2, p.B2);
  const Vec3 exact_f = dipole_force(m1, m2, p.c2 - p.c1);
  const ChargeModel model({ball(p.c1, p.a1, p.d1, p.B1), ball(p.c2, p.a2, p.d2, p.B2)});
  const BatchFieldFunction field = [&](const std::vector<Vec3>& xs) { return model.B(xs); };
  // The field on the sphere is smooth (nearest source 1.8 mm away): 48 x 96 points resolve
  // it to round-off level for this geometry.
  const ForceTorque ft = maxwell_stress_on_sphere(field, p.c2, 1.25 * p.a2, p.c2, 48, 96);
  EXPECT_LT((ft.force - exact_f).norm(), force_tol * exact_f.norm())
      << ft.force.transpose() << " vs " << exact_f.transpose();
}

TEST(ChargeForce, MaxwellStressTorqueOfDipoleInUniformField) {
  // A magnetized sphere in a uniform B0: torque m x B0 (about any point), zero force.
  const double a = 0.01;
  const Vec3 d(0.0, 0.6, 0.8), B0(0.3, -0.1, 0.05);
  const Vec3 c(0.002, 0.001, -0.003);
  const ChargeModel model({ball(c, a, d, 1.1)});
  const FieldFunction field = [&](const Vec3& x) { return Vec3(model.B(x) + B0); };
  const ForceTorque ft = maxwell_stress_on_sphere(field, c, 1.5 * a, c, 24, 48);
  const Vec3 exact = moment(a, d, 1.1).cross(B0);
  EXPECT_LT((ft.torque - exact).norm(), force_tol * exact.norm());
  EXPECT_LT(ft.force.norm(), force_tol * exact.norm() / a);
  // About another point the torque gains r x F = 0.
  const ForceTorque shifted = maxwell_stress_on_sphere(field, c, 1.5 * a, Vec3(0.05, 0, 0), 24, 48);
  EXPECT_LT((shifted.torque - exact).norm(), force_tol * exact.norm());
}

} // namespace
} // namespace magfem
