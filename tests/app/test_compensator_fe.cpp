// Gravity compensator, thesis Table 4.2 design (paper_targets.md B), by FE through the sweep
// pipeline against the charge model and the published figures (issue 6). Several minutes and
// ~3 GB per position on 2 cores, so it is not in the default suite:
//   build/tests/app/test_app_compensator_fe --gtest_also_run_disabled_tests
#include <gtest/gtest.h>

#include <cmath>

#include "app/sweep.hpp"
#include "case_helpers.hpp"

using namespace magfem;

TEST(CompensatorFE, DISABLED_Table42CurvesAgreeWithTheChargeModelAndThePublishedFigures) {
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
  // measured 0.8 % (torque at 60 deg) at the example's mesh.
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
