// Gravity compensator, thesis Table 4.2 design (paper_targets.md B), by FE through the sweep
// pipeline against the charge model and the published figures (issue 6). At the example's
// mesh 1.5-2 min on 2 cores, so in the long tier (bash scripts/test.sh --long); a coarse
// variant runs in the default suite and watches the same accuracy for drift.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "studies/sweep.hpp"
#include "tests/case_helpers.hpp"

using namespace magfem;

TEST(CompensatorFE, LongTable42CurvesAgreeWithTheChargeModelAndThePublishedFigures) {
  const auto spec = read_case(test::example("3d/compensator_table42.yaml"));
  SweepOptions o;
  o.group = "outer";
  o.axis = Eigen::Vector3d::UnitY();
  o.angles_deg = {0, 60, 90};
  const auto fe = run_sweep(spec, o);
  o.analytic = true;
  const auto charge = run_sweep(spec, o);
  for (const auto& r : fe)
    ASSERT_TRUE(r.ok) << r.error;
  for (const auto& r : charge)
    ASSERT_TRUE(r.ok) << r.error;

  // Published (sec. 4.4): 12 Nm at 90 deg, 533 N attraction at 0 deg (the outer magnet is
  // pulled down, -z), 124 N repulsion at 60 deg; 5 % as paper_targets.md states.
  EXPECT_NEAR(charge[2].torque.y(), 12.0, 0.05 * 12.0);
  EXPECT_NEAR(charge[0].force.z(), -533.0, 0.05 * 533.0);
  EXPECT_NEAR(charge[1].force.z(), 124.0, 0.05 * 124.0);
  EXPECT_NEAR(fe[2].torque.y(), 12.0, 0.05 * 12.0);

  // FE and analytic curves within 1 % of the peak of each other (the figure);
  // measured 0.65 % (torque at 90 deg) and 0.82 % (force at 0 deg) at the example's mesh
  // (docs/example_accuracy.md). The mesher change that coarsened spheres' chord limit at
  // order 2 (5a8e991) had moved the torque to 1.30 %: this bound fails on that.
  const double peak_torque = std::abs(charge[2].torque.y());
  const double peak_force = std::abs(charge[0].force.z());
  for (std::size_t i = 0; i < fe.size(); ++i) {
    std::cout << fe[i].angle_deg << " deg: FE T " << fe[i].torque.transpose() << " F "
              << fe[i].force.transpose() << "; charge T " << charge[i].torque.transpose() << " F "
              << charge[i].force.transpose() << "\n";
    EXPECT_LT((fe[i].torque - charge[i].torque).cwiseAbs().maxCoeff(), 0.01 * peak_torque);
    EXPECT_LT((fe[i].force - charge[i].force).cwiseAbs().maxCoeff(), 0.01 * peak_force);
    // Parasitic torque components below 1 % of the peak (sec. 4.3: zero by symmetry).
    EXPECT_LT(std::abs(fe[i].torque.x()), 0.01 * peak_torque);
    EXPECT_LT(std::abs(fe[i].torque.z()), 0.01 * peak_torque);
  }
}

// The default suite's watch on the example's accuracy: the same case and sweep at twice the
// element size (--mesh-scale 2: 200-280k P2 unknowns, ~10 s per position), at the two angles
// where FE and the charge model differ most. Measured (commit of this test): torque 1.27 %
// (60 deg) and 1.47 % (90 deg), force 2.21 % and 2.06 % of the peaks. Bounds: 15 % above the
// worst of those, so that a change of the mesher or the stress tensor that loses accuracy
// fails here rather than in the long tier only: the chord-limit change that moved the example
// from 0.65 % to 1.30 % gives 3.2 % (torque) and 12.5 % (force) at this mesh.
TEST(CompensatorFE, CoarseMeshStaysWithinItsMeasuredDiscretisationError) {
  const auto spec = read_case(test::example("3d/compensator_table42.yaml"));
  SweepOptions o;
  o.group = "outer";
  o.axis = Eigen::Vector3d::UnitY();
  o.angles_deg = {60, 90};
  o.mesh_scale = 2;
  const auto fe = run_sweep(spec, o);
  o.analytic = true;
  const auto charge = run_sweep(spec, o);
  ASSERT_EQ(fe.size(), 2u);
  for (std::size_t i = 0; i < fe.size(); ++i) {
    ASSERT_TRUE(fe[i].ok) << fe[i].error;
    ASSERT_TRUE(charge[i].ok) << charge[i].error;
  }
  // The peaks of the charge model's curves (exact for these bodies): 12.365 N m at 90 deg and
  // the 536 N attraction at 0 deg.
  o.angles_deg = {0};
  const auto attraction = run_sweep(spec, o);
  ASSERT_TRUE(attraction.at(0).ok);
  const double peak_torque = std::abs(charge[1].torque.y());
  const double peak_force = std::abs(attraction[0].force.z());
  for (std::size_t i = 0; i < fe.size(); ++i) {
    const double dt = (fe[i].torque - charge[i].torque).cwiseAbs().maxCoeff() / peak_torque;
    const double df = (fe[i].force - charge[i].force).cwiseAbs().maxCoeff() / peak_force;
    std::printf("%g deg: torque %.2f %%, force %.2f %% of the peaks (%ld unknowns)\n",
                fe[i].angle_deg, 100 * dt, 100 * df, fe[i].unknowns);
    EXPECT_LT(dt, 1.15 * 0.0147) << fe[i].angle_deg << " deg";
    EXPECT_LT(df, 1.15 * 0.0221) << fe[i].angle_deg << " deg";
  }
}
