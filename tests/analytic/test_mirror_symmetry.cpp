// Mirror symmetry of two groups of magnets (analytic/mirror_symmetry.hpp) and its use by
// the face-pair cubature (analytic/pair_interaction.hpp): the segment arrays' plane of
// tilt is found with the expected pairing and signs, a broken symmetry or a torque point off
// the plane finds none, and integrating one pair of each mirrored two gives the full
// computation's force and torque (a wrong sign of the mirrored force or of the axial torque
// would show as an error of the size of the result).
#include <cmath>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "analytic/interaction_cases.hpp"
#include "analytic/mirror_symmetry.hpp"
#include "analytic/pair_interaction.hpp"

namespace magfem {
namespace {

using Vec3 = Eigen::Vector3d;

InteractionCase reduced_segment_case() {
  // The test suite's reduced spherical coupling (2 x 4 rotor segments tilted 20 deg about y,
  // 1 x 4 half shell, 2 mm gap).
  const Placement tilt = Placement{}.rotated(Vec3::UnitY(), 20 * deg_to_rad, Vec3::Zero());
  return {"segment arrays 8 in 4", segment_array(0.040, 0.055, 2, 4, 1.3, pi, tilt),
          segment_array(0.057, 0.065, 1, 4, 1.3, 0.5 * pi)};
}

TEST(MirrorSymmetry, SegmentArraysMirrorInTheirPlaneOfTilt) {
  const InteractionCase c = segment_coupling_case();
  const auto m = find_mirror_symmetry(c.on, c.by, Vec3::Zero());
  ASSERT_TRUE(m.has_value());
  EXPECT_NEAR(std::abs(m->normal.y()), 1, 1e-15);
  // Segment (i, j) of 8 per ring spans phi in [j, j + 1] 45 deg: y -> -y maps it onto
  // (i, 7 - j), whose magnetization sign (-1)^(i + j) is the opposite.
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 8; ++j) {
      EXPECT_EQ(m->image_on[8 * i + j], 8 * i + 7 - j);
      EXPECT_EQ(m->sign_on[8 * i + j], -1);
    }
  for (int j = 0; j < 8; ++j)
    EXPECT_EQ(m->image_by[j], 7 - j);
}

TEST(MirrorSymmetry, BrokenSymmetryOrTorquePointOffThePlaneFindsNone) {
  InteractionCase c = reduced_segment_case();
  EXPECT_TRUE(find_mirror_symmetry(c.on, c.by, Vec3(0.001, 0, -0.002)).has_value());
  EXPECT_FALSE(find_mirror_symmetry(c.on, c.by, Vec3(0, 0.001, 0)).has_value());
  c.by[1].B_r *= 1.01;
  EXPECT_FALSE(find_mirror_symmetry(c.on, c.by, Vec3::Zero()).has_value());
}

// Integrating one pair of each mirrored two against every pair: both are the same cubature
// at the same tolerance, up to ties broken differently in the mirrored boxes' splits, so they
// agree to their printed accuracies and to 1e-7 of |F| and |T| (measured: <= 4e-9), with
// about half the kernel evaluations (at most 0.6 of them: pairs mapped onto themselves, e.g.
// the prototype's cylinders in the plane, are integrated in full; measured 0.50 and 0.54).
void expect_mirror_matches_full(const InteractionCase& c, const Vec3& torque_point) {
  PairInteractionOptions full;
  full.mirror_symmetry = false;
  const PairInteraction a = pair_interaction(c.on, c.by, torque_point);
  const PairInteraction b = pair_interaction(c.on, c.by, torque_point, full);
  ASSERT_TRUE(a.mirrored) << c.name;
  const double df = (a.on_A.force - b.on_A.force).norm();
  const double dt = (a.on_A.torque - b.on_A.torque).norm();
  EXPECT_LT(df, 1e-7 * b.on_A.force.norm()) << c.name;
  EXPECT_LT(dt, 1e-7 * b.on_A.torque.norm()) << c.name;
  EXPECT_LE(df, a.force_error + b.force_error) << c.name;
  EXPECT_LE(dt, a.torque_error + b.torque_error) << c.name;
  EXPECT_LT(a.kernel_evals, 0.6 * b.kernel_evals) << c.name;
}

TEST(MirrorSymmetry, MirroredPairsGiveTheFullInteraction) {
  expect_mirror_matches_full(reduced_segment_case(), Vec3(0.001, 0, -0.002));
  expect_mirror_matches_full(prototype_case(0.0125, 30), Vec3::Zero());
}

} // namespace
} // namespace magfem
