// Coil conductor geometry and the coil set: volume rules (volume, closed current, resistance),
// placement (a moved coil's field is the moved field), Lorentz force between coaxial coils from
// the source field and the volume rule against the exact force of validation/, action and
// reaction, and the threaded batch evaluation.
#include <cmath>
#include <initializer_list>
#include <random>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "sources/coil_field.hpp"
#include "sources/coil_set.hpp"
#include "analytic/coil_closed_forms.hpp"

namespace magfem {
namespace {

std::vector<Coil3D> sample_coils() {
  Coil3D s;
  s.name = "solenoid";
  s.shape = Solenoid{0.01, 0.02, 0.04};
  s.turns = 200;
  s.current = 1.5;
  Coil3D sc;
  sc.name = "sphere";
  sc.shape = SphericalCoil{0.063, 0.072, 3.7 * deg_to_rad, 18.4 * deg_to_rad};
  sc.turns = 300;
  sc.current = -0.8;
  Coil3D r;
  r.name = "racetrack";
  r.shape = Racetrack{0.1, 0.05, 0.025, 0.025, 0.1};
  r.turns = 2742;
  r.current = 1.0;
  return {s, sc, r};
}

TEST(CoilGeometry, VolumeRulesAreExactForVolumeAndClosedCurrent) {
  for (const Coil3D& c : sample_coils()) {
    const CoilField f(c);
    for (const int order : {2, 5}) {
      double volume = 0, abs_j = 0;
      Vec3 j = Vec3::Zero();
      for (const CoilQuadraturePoint& q : f.volume_quadrature(order)) {
        volume += q.weight;
        j += q.weight * q.j_per_ampere;
        abs_j += q.weight * q.j_per_ampere.norm();
        EXPECT_TRUE(f.contains(q.x)) << c.name;
        EXPECT_NEAR(q.j_per_ampere.norm(), c.turns / f.cross_section_area(),
                    1e-12 * c.turns / f.cross_section_area());
        // The rule's current density is the coil's, per ampere.
        EXPECT_LT((c.current * q.j_per_ampere - f.current_density(q.x)).norm(),
                  1e-9 * q.j_per_ampere.norm());
      }
      EXPECT_NEAR(volume, f.volume(), 1e-13 * f.volume()) << c.name;
      EXPECT_LT(j.norm(), 1e-13 * abs_j) << c.name;
    }
  }
}

TEST(CoilGeometry, SolenoidResistanceAndMeanTurnLength) {
  Coil3D c = sample_coils()[0];
  c.fill_factor = 0.55;
  c.resistivity = 1.7e-8;
  const CoilField f(c);
  const double mtl = pi * (0.01 + 0.02); // circumference at the mean radius
  EXPECT_NEAR(f.mean_turn_length(), mtl, 1e-15);
  // Wire length N mtl, wire cross-section fill (r_o - r_i) L / N.
  const double r = c.resistivity * c.turns * mtl / (c.fill_factor * 0.01 * 0.04 / c.turns);
  EXPECT_NEAR(f.resistance(), r, 1e-12 * r);
}

TEST(CoilGeometry, VolumeRuleIntegratesSmoothFieldsToHighOrder) {
  // int rho^2 dV over the solenoid = 2 pi L (r_o^4 - r_i^4) / 4, exact at order >= 2.
  const CoilField f(sample_coils()[0]);
  double s = 0;
  for (const CoilQuadraturePoint& q : f.volume_quadrature(3)) {
    s += q.weight * (q.x.x() * q.x.x() + q.x.y() * q.x.y());
  }
  const double exact = 2 * pi * 0.04 * (std::pow(0.02, 4) - std::pow(0.01, 4)) / 4;
  EXPECT_NEAR(s, exact, 1e-13 * exact);
}

TEST(CoilGeometry, APlacedCoilGivesTheMovedField) {
  for (Coil3D c : sample_coils()) {
    const CoilField local(c);
    c.placement = Placement{}.rotated(Vec3(1, -2, 0.5), 0.7, Vec3(0.01, 0.0, -0.02));
    c.placement.translation += Vec3(0.03, 0.05, -0.01);
    const CoilField moved(c);
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(-0.15, 0.15);
    for (int t = 0; t < 40; ++t) {
      const Vec3 x(u(gen), u(gen), u(gen));
      const Vec3 expected = c.placement.rotation * local.H(x);
      // Same computation up to the round-off of the placement (1e-16 relative in the point),
      // amplified at worst by a rule switching order between the two evaluations.
      EXPECT_LT((moved.H(c.placement.to_global(x)) - expected).norm(), 1e-7 * expected.norm())
          << c.name;
      EXPECT_EQ(moved.contains(c.placement.to_global(x)), local.contains(x));
    }
    EXPECT_LT((moved.magnetic_moment_per_ampere() -
               c.placement.rotation * local.magnetic_moment_per_ampere())
                  .norm(),
              1e-12 * local.magnetic_moment_per_ampere().norm());
  }
}

// F on coil b = int J_b x mu0 H_a dV over b's volume rule, against the exact axial force of
// validation/ (Maxwell's formula differentiated, integrated over both cross-sections). The
// coils are 5 mm apart, so H_a is smooth over b and the rule of order 10 converges (checked
// against order 12); the source field contributes its 1e-8.
TEST(CoilGeometry, LorentzForceBetweenCoaxialCoilsMatchesTheExactForce) {
  Coil3D a, b;
  a.shape = Solenoid{0.01, 0.02, 0.02};
  a.turns = 100;
  a.current = 2.0;
  b.shape = Solenoid{0.012, 0.025, 0.01};
  b.turns = 50;
  b.current = 3.0;
  b.placement.translation = Vec3(0, 0, 0.02); // b spans z in [0.015, 0.025]
  const CoilField fa(a), fb(b);
  auto force = [](const CoilField& on, const CoilField& from, int order) {
    Vec3 f = Vec3::Zero();
    for (const CoilQuadraturePoint& q : on.volume_quadrature(order)) {
      f += q.weight * on.coil().current * q.j_per_ampere.cross(mu0 * from.H(q.x));
    }
    return f;
  };
  const Vec3 on_b = force(fb, fa, 10), on_a = force(fa, fb, 10);
  EXPECT_LT((on_b - force(fb, fa, 12)).norm(), 1e-9 * on_b.norm());
  const double exact = coaxial_axial_force(CoaxialCoil{0.01, 0.02, -0.01, 0.01, 100},
                                           CoaxialCoil{0.012, 0.025, 0.015, 0.025, 50}, 2.0, 3.0);
  EXPECT_LT(exact, 0.0); // like currents attract
  EXPECT_NEAR(on_b.z(), exact, 1e-7 * std::abs(exact));
  EXPECT_NEAR(on_b.x(), 0.0, 1e-9 * std::abs(exact));
  EXPECT_NEAR(on_b.y(), 0.0, 1e-9 * std::abs(exact));
  // Action = reaction, to the accuracy of the two source fields.
  EXPECT_LT((on_a + on_b).norm(), 1e-7 * on_b.norm());
}

TEST(CoilSet, SumsTheCoilsAndGivesTheSameBatchOnAnyNumberOfThreads) {
  const CoilSet set(sample_coils());
  ASSERT_EQ(set.size(), 3);
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  std::vector<Vec3> points;
  for (int t = 0; t < 1500; ++t) {
    points.emplace_back(u(gen), u(gen), u(gen));
  }
  std::vector<Vec3> one, two, three;
  set.H_at(points, one, 1);
  set.H_at(points, two, 2);
  set.H_at(points, three, 3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(one[i], two[i]);
    EXPECT_EQ(one[i], three[i]);
    if (i % 100 == 0) {
      EXPECT_EQ(one[i], set.H(points[i]));
      const Vec3 sum = set.H_of(0, points[i]) + set.H_of(1, points[i]) + set.H_of(2, points[i]);
      EXPECT_LT((sum - one[i]).norm(), 1e-14 * one[i].norm());
    }
  }
}

} // namespace
} // namespace magfem
