// Spherical gravity compensator of thesis ch. 4, Table 4.2 design (paper_targets.md B):
// inner solid hemisphere R 29 mm, parallel along +z; outer hemispherical shell 30..43 mm,
// radial; B_r 1.3 T; the outer magnet rotated by theta about the y axis through the centre.
// "Opposed at 0 deg" is read as the outer magnetization pointing inwards (towards the
// centre, i.e. -z at the top where the inner one points +z): this reading gives the
// published 533 N attraction at 0 deg (the outward reading gives the same numbers with the
// opposite sign, i.e. 533 N repulsion).
// Published: torque amplitude 12 Nm at 90 deg, axial force 533 N attraction at 0 deg,
// zero at 36 deg, 124 N repulsion at 60 deg. Tolerances from paper_targets: 5 % on torque
// and forces, 3 deg on the angle (the thesis's own MST/FE figures carry that uncertainty).
#include <cmath>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "validation/analytic_force.hpp"

namespace magfem {
namespace {

using Vec3 = Eigen::Vector3d;

AnalyticMagnet inner_hemisphere() {
  AnalyticMagnet m;
  m.name = "inner";
  m.shape = SphericalSegment{0, 0.029, 0, pi / 2, 0, 2 * pi};
  m.magnetization.pattern = Magnetization::Pattern::parallel;
  m.magnetization.direction = Vec3::UnitZ();
  m.B_r = 1.3;
  return m;
}

AnalyticMagnet outer_shell(double theta) {
  AnalyticMagnet m;
  m.name = "outer";
  m.shape = SphericalSegment{0.030, 0.043, 0, pi / 2, 0, 2 * pi};
  m.magnetization.pattern = Magnetization::Pattern::radial;
  m.magnetization.sign = -1; // inwards: opposed to the inner magnet at theta = 0
  m.B_r = 1.3;
  m.placement = Placement{}.rotated(Vec3::UnitY(), theta, Vec3::Zero());
  return m;
}

// Force and torque (about the centre) on the inner magnet.
ForceTorque on_inner(double theta_deg) {
  ChargeInteractionOptions opt;
  opt.tolerance = 1e-4; // converged to < 1e-5 relative against 1e-6 (536.228 N, 12.3686 Nm)
  opt.field.tolerance = 1e-4;
  return charge_interaction({inner_hemisphere()}, {outer_shell(theta_deg * deg_to_rad)},
                            Vec3::Zero(), opt);
}

TEST(ChargeGravityCompensator, Table42TorqueAndForces) {
  const ForceTorque at0 = on_inner(0), at60 = on_inner(60), at90 = on_inner(90);
  // Attraction: the inner magnet is pulled up into the dome (+z), 533 N.
  EXPECT_NEAR(at0.force.z(), 533.0, 0.05 * 533.0);
  // Repulsion at 60 deg: 124 N.
  EXPECT_NEAR(at60.force.z(), -124.0, 0.05 * 124.0);
  // Torque about the rotation axis at 90 deg: 12 Nm in magnitude (restoring sign: the torque
  // on the outer magnet, -T_y here, drives it back towards 0 deg).
  EXPECT_NEAR(std::abs(at90.torque.y()), 12.0, 0.05 * 12.0);
  EXPECT_LT(at90.torque.y(), 0);
  // No torque about the other axes (sec. 4.3: the T_theta component vanishes), < 1 % of peak.
  EXPECT_LT(std::hypot(at90.torque.x(), at90.torque.z()), 0.01 * std::abs(at90.torque.y()));
  EXPECT_LT(std::hypot(at60.torque.x(), at60.torque.z()), 0.01 * std::abs(at90.torque.y()));
  RecordProperty("force_z_0deg_N", std::to_string(at0.force.z()));
  RecordProperty("force_z_60deg_N", std::to_string(at60.force.z()));
  RecordProperty("torque_y_90deg_Nm", std::to_string(at90.torque.y()));
}

TEST(ChargeGravityCompensator, AxialForceChangesSignNear36Degrees) {
  // Secant step between 33 and 39 deg (F_z is smooth and monotone there).
  const double a = 33, b = 39;
  const double fa = on_inner(a).force.z(), fb = on_inner(b).force.z();
  ASSERT_GT(fa, 0);
  ASSERT_LT(fb, 0);
  const double zero = a - fa * (b - a) / (fb - fa);
  RecordProperty("force_zero_deg", std::to_string(zero));
  EXPECT_NEAR(zero, 36.0, 3.0);
}

} // namespace
} // namespace magfem
