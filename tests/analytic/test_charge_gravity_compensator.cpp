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
#include <utility>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "analytic/analytic_force.hpp"

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

// A compensator of any of the four topologies of Fig. 4.3 (radial/parallel outer and inner),
// opposed at 0 deg, outer rotated by theta about y.
struct Topology {
  double r_in, gap, r_out, B_r_in, B_r_out;
  bool outer_radial, inner_parallel;
};

std::pair<AnalyticMagnet, AnalyticMagnet> compensator(const Topology& t, double theta) {
  AnalyticMagnet in, out;
  in.shape = SphericalSegment{0, t.r_in, 0, pi / 2, 0, 2 * pi};
  in.B_r = t.B_r_in;
  in.magnetization.pattern =
      t.inner_parallel ? Magnetization::Pattern::parallel : Magnetization::Pattern::radial;
  in.magnetization.direction = Vec3::UnitZ(); // radial: outwards
  out.shape = SphericalSegment{t.r_in + t.gap, t.r_out, 0, pi / 2, 0, 2 * pi};
  out.B_r = t.B_r_out;
  out.magnetization.pattern =
      t.outer_radial ? Magnetization::Pattern::radial : Magnetization::Pattern::parallel;
  out.magnetization.direction = -Vec3::UnitZ();
  out.magnetization.sign = t.outer_radial ? -1 : 1; // radial: inwards
  out.placement = Placement{}.rotated(Vec3::UnitY(), theta, Vec3::Zero());
  out.magnetization = out.magnetization.rotated(out.placement.rotation, Vec3::Zero());
  return {in, out};
}

// Torque about the centre on the outer magnet.
Vec3 torque_on_outer(const Topology& t, double theta_deg) {
  const auto [in, out] = compensator(t, theta_deg * deg_to_rad);
  ChargeInteractionOptions opt;
  opt.tolerance = opt.field.tolerance = 1e-4;
  return -charge_interaction({in}, {out}, Vec3::Zero(), opt).torque;
}

// Force and torque (about the centre) on the inner magnet.
ForceTorque on_inner(double theta_deg) {
  ChargeInteractionOptions opt;
  // Converged to < 1e-5 relative against 1e-6 (536.315 N, -126.683 N, -12.3653 Nm); the
  // torque agrees with a Maxwell-stress integration on r = 29.5 mm (200 x 400 points) to 1e-5.
  opt.tolerance = 1e-4;
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

TEST(ChargeGravityCompensator, Section45RemanenceVariantsAndElbowDesign) {
  // Sec. 4.5: outer B_r 0.65 T gives 6.1 Nm, both 0.65 T give 3.0 Nm; sec. 4.4.1: R_in 35,
  // R_out 49.6 mm gives 1.58 times the torque. 5 % (paper_targets B).
  const Topology base{0.029, 0.001, 0.043, 1.3, 1.3, true, true};
  const double t = torque_on_outer(base, 90).y();
  Topology bonded = base;
  bonded.B_r_out = 0.65;
  EXPECT_NEAR(torque_on_outer(bonded, 90).y(), 6.1, 0.05 * 6.1);
  bonded.B_r_in = 0.65;
  EXPECT_NEAR(torque_on_outer(bonded, 90).y(), 3.0, 0.05 * 3.0);
  const Topology elbow{0.035, 0.001, 0.0496, 1.3, 1.3, true, true};
  EXPECT_NEAR(torque_on_outer(elbow, 90).y() / t, 1.58, 0.05 * 1.58);
}

TEST(ChargeGravityCompensator, NoParasiticTorqueWhereTheRimsCross) {
  // Sec. 4.3: the torque has no component other than about the rotation axis (mirror
  // symmetry y -> -y). At 20 deg the outer rim passes 1 mm from the inner one, where the
  // field of the outer magnet is singular: a quadrature that does not resolve its edges
  // breaks the symmetry (an error-estimate-only adaptive scheme gave 0.9 % of the torque).
  for (const Topology& t : {Topology{0.025, 0.001, 0.036, 1.3, 1.3, true, false},
                            Topology{0.025, 0.001, 0.036, 1.3, 1.3, true, true}}) {
    const Vec3 torque = torque_on_outer(t, 20);
    EXPECT_GT(std::abs(torque.y()), 1.0);
    EXPECT_LT(std::hypot(torque.x(), torque.z()), 1e-4 * std::abs(torque.y()))
        << torque.transpose();
  }
}

} // namespace
} // namespace magfem
