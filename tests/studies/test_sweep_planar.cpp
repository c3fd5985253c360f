// Planar 2D sweep (magfem sweep --rotate on a planar case): the RE25-like motor's rotor turned
// through a revolution. Its magnet is a diametrically magnetized disc inside a concentric
// linear casing: turning the rotor turns its field rigidly, so the torque against a fixed
// winding is a pure first harmonic, T(a) = T(0) cos a + T(90) sin a. The mesh is new at every
// angle (the magnet's polygon turns), so the identities hold to the mesh's error only.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "studies/sweep_planar.hpp"
#include "tests/case_helpers.hpp"
#include "core/constants.hpp"
#include "core/input_error.hpp"

using namespace magfem;

namespace {

SweepOptions rotor_sweep(std::vector<double> angles) {
  SweepOptions o;
  o.group = "rotor";
  o.axis = Eigen::Vector3d::UnitZ();
  o.angles_deg = std::move(angles);
  o.jobs = 2;
  return o;
}

} // namespace

// Measured: the harmonic identities within 0.13 % of the peak torque (the turned polygon's
// mesh), the force on the rotor below 0.9 % of peak torque / radius (zero by symmetry): bounds
// 0.5 % and 2 %. Would fail on: the angle ignored (T(180) = T(0)), a clockwise turn or the
// magnetization left unturned (T(90) of the wrong sign or zero), a torque about the wrong
// point (the rotor's force is small, so the point is checked below).
TEST(PlanarSweep, RotorTorqueIsAFirstHarmonicOfTheRotorAngle) {
  const auto spec = read_case(test::example("2d/re25_motor_torque.yaml"));
  const auto rows = run_sweep_planar(spec, rotor_sweep({0, 45, 90, 180, 270}));
  ASSERT_EQ(rows.size(), 5u);
  for (const auto& r : rows) {
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.method, "arkkio_band");
    std::printf("%5.0f deg: Tz %.6f N m/m, F (%.5f, %.5f) N/m\n", r.angle_deg, r.torque.z(),
                r.force.x(), r.force.y());
  }
  const double t0 = rows[0].torque.z(), t90 = rows[2].torque.z();
  const double peak = std::hypot(t0, t90);
  ASSERT_GT(peak, 1.0); // 3.78 N m/m: the coil at 2 x 100 x 2 A
  const double tol = 5e-3 * peak;
  EXPECT_NEAR(rows[1].torque.z(), (t0 + t90) / std::sqrt(2.0), tol);
  EXPECT_NEAR(rows[3].torque.z(), -t0, tol);
  EXPECT_NEAR(rows[4].torque.z(), -t90, tol);
  for (const auto& r : rows)
    EXPECT_LT(r.force.head<2>().norm(), 0.02 * peak / 0.010);
}

// Turning the round magnet by 45 deg is the same device as magnetizing it at 45 deg: the same
// disc, so the same mesh, and the torque must agree to round-off (an unturned magnetization
// gives T(0), 41 % off). The turn is counter-clockwise about +z: a sector of the group moves
// from [-30, 30] to [60, 120] deg at +90, and its magnetization from +x to +y.
TEST(PlanarSweep, TurningTheRotorEqualsTurningItsMagnetization) {
  const auto spec = read_case(test::example("2d/re25_motor_torque.yaml"));
  const auto rows = run_sweep_planar(spec, rotor_sweep({45}));
  ASSERT_TRUE(rows.at(0).ok) << rows[0].error;
  CaseSpec turned = spec;
  turned.regions[0].magnetization.direction = Eigen::Vector3d(1, 1, 0).normalized();
  turned.forces = {turned.forces[1]}; // rotor_band
  turned.probes.clear();
  turned.write_vtu = false;
  const auto run = run_case_2d(std::move(turned));
  const double expected = run->forces.front().torque.z();
  EXPECT_NEAR(rows[0].torque.z(), expected, 1e-9 * std::abs(expected));

  CaseSpec with_sector = spec;
  ASSERT_EQ(with_sector.regions[2].name, "coil_go");
  with_sector.regions[2].group = "rotor";
  with_sector.regions[2].magnetization.direction = Eigen::Vector3d::UnitX();
  const CaseSpec q = rotate_group_planar(with_sector, "rotor", pi / 2, Eigen::Vector3d::Zero());
  const auto& sector = std::get<AnnularSector>(q.geometry2d.parts[2].shape);
  EXPECT_NEAR(sector.angle_start, 60 * deg_to_rad, 1e-12);
  EXPECT_NEAR(sector.angle_end, 120 * deg_to_rad, 1e-12);
  EXPECT_NEAR((q.regions[2].magnetization.direction - Eigen::Vector3d::UnitY()).norm(), 0, 1e-12);
  EXPECT_NEAR((q.regions[0].magnetization.direction - Eigen::Vector3d::UnitY()).norm(), 0, 1e-12);
  // Regions outside the group stay.
  EXPECT_EQ(std::get<AnnularSector>(q.geometry2d.parts[3].shape).angle_start,
            std::get<AnnularSector>(spec.geometry2d.parts[3].shape).angle_start);
}

// The torque is about the sweep's point: at angle 0 the device and its mesh do not depend on
// the point, so the torques about p and about the origin differ by exactly p x F.
TEST(PlanarSweep, TorqueIsAboutTheSweepPoint) {
  const auto spec = read_case(test::example("2d/re25_motor_torque.yaml"));
  const auto at_origin = run_sweep_planar(spec, rotor_sweep({0}));
  auto o = rotor_sweep({0});
  o.point = Eigen::Vector3d(0.002, -0.003, 0);
  const auto at_p = run_sweep_planar(spec, o);
  ASSERT_TRUE(at_origin.at(0).ok && at_p.at(0).ok);
  const Eigen::Vector3d F = at_origin[0].force;
  ASSERT_GT(F.head<2>().norm(), 1e-3); // p x F must be visible
  const double p_cross_F = o.point.x() * F.y() - o.point.y() * F.x();
  EXPECT_NEAR(at_p[0].torque.z(), at_origin[0].torque.z() - p_cross_F, 1e-3 * std::abs(p_cross_F));
}

TEST(PlanarSweep, BadRequestsNameTheOption) {
  const auto spec = read_case(test::example("2d/re25_motor_torque.yaml"));
  auto o = rotor_sweep({0});
  o.axis = Eigen::Vector3d::UnitX();
  EXPECT_THROW(run_sweep_planar(spec, o), InputError);
  o = rotor_sweep({0});
  o.group = "stator";
  EXPECT_THROW(run_sweep_planar(spec, o), InputError);
  // A group without current and no band or circle force around it: the message says what to add.
  CaseSpec bare = spec;
  bare.forces.clear();
  try {
    run_sweep_planar(bare, rotor_sweep({0}));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("type: band"), std::string::npos) << e.what();
  }
  const auto axi = read_case(test::example("axi/voice_coil_magnet.yaml"));
  EXPECT_THROW(rotate_group_planar(axi, "coil", 0.1, Eigen::Vector3d::Zero()), InputError);
}
