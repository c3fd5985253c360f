// The adaptive loop's stopping rule on made-up passes (pipeline/adapt_loop.hpp): a named
// quantity's error is the change between passes extrapolated, and never less than the error
// the result's own one-mesh estimate gives (a force by the stress tensor). The passes'
// change cannot see an error every pass shares; the one-mesh estimate can (two spheres' force:
// change 0.01 %, true error 0.19 %, one-mesh estimate 0.19 %).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "pipeline/adapt_loop.hpp"

namespace magfem {
namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();

// Three passes of a quantity converging like 10, 10.5, 10.501 (energy already within the
// target), each pass's one-mesh estimate `mesh_pct`.
AdaptHistory three_passes(double accuracy_pct, double mesh_pct) {
  AdaptSpec spec;
  spec.accuracy_pct = accuracy_pct;
  spec.quantities = {"forces.f.force"};
  spec.max_passes = 3;
  const double values[] = {10.0, 10.5, 10.501};
  AdaptSteps steps;
  steps.solve = [&](int pass) {
    return AdaptMeasure{1000u * pass, 2000 * pass, 1.0, 1e-4, {values[pass - 1]}, {mesh_pct}};
  };
  steps.plan = [](double, bool) { return AdaptPlan{1e3, ""}; };
  return run_adapt_loop(spec, steps, {});
}

TEST(AdaptLoop, AQuantitysErrorIsNeverBelowItsOneMeshEstimate) {
  // Without a one-mesh estimate: the change 0.001 extrapolated with rho = 0.25 (its floor),
  // 0.001 / 3 of 10.501: 0.0032 %, below a 0.3 % target.
  const AdaptHistory plain = three_passes(0.3, nan);
  ASSERT_EQ(plain.passes.size(), 3u);
  EXPECT_NEAR(plain.passes[2].quantity_error_pct[0], 100 * (0.001 / 3) / 10.501, 1e-12);
  EXPECT_TRUE(plain.converged);
  // With one of 0.4 %: that is the estimate, and 0.3 % is not reached.
  const AdaptHistory floored = three_passes(0.3, 0.4);
  EXPECT_DOUBLE_EQ(floored.passes[2].quantity_error_pct[0], 0.4);
  EXPECT_FALSE(floored.converged);
  EXPECT_EQ(floored.stop_reason, "max_passes (3) reached");
  // The first pass has no change to compare: unknown, whatever the one-mesh estimate says.
  EXPECT_TRUE(std::isnan(floored.passes[0].quantity_error_pct[0]));
  // A one-mesh estimate below the extrapolated change does not lower it.
  EXPECT_NEAR(three_passes(0.3, 1e-6).passes[1].quantity_error_pct[0], 100 * 0.5 / 10.5, 1e-12);
}

TEST(AdaptLoop, OneMeshErrorOfAForceQuantityIsItsComponentsEstimate) {
  ForceResult f;
  f.name = "f";
  f.force = Eigen::Vector3d(3, 0, 4);
  f.torque = Eigen::Vector3d(0, -2, 0);
  f.estimated = true;
  f.force_err = Eigen::Vector3d(0.03, 0, 0.04);
  f.torque_err = Eigen::Vector3d(0, 0.01, 0);
  auto pct = [&](const char* component) {
    return adapt_quantity_mesh_error_pct(AdaptQuantity{AdaptQuantity::Kind::force, "f", component},
                                         {f});
  };
  EXPECT_DOUBLE_EQ(pct("force"), 1.0);  // |(0.03, 0, 0.04)| / |(3, 0, 4)|
  EXPECT_DOUBLE_EQ(pct("torque"), 0.5); // 0.01 / 2
  EXPECT_DOUBLE_EQ(pct("Fz"), 1.0);     // 0.04 / 4
  EXPECT_DOUBLE_EQ(pct("Ty"), 0.5);     // 0.01 / |-2|
  EXPECT_TRUE(std::isnan(pct("Fy")));   // a zero component has no relative error
  f.estimated = false;                  // a method without an estimate: none
  EXPECT_TRUE(std::isnan(pct("force")));
  EXPECT_TRUE(std::isnan(
      adapt_quantity_mesh_error_pct(AdaptQuantity{AdaptQuantity::Kind::energy, "", ""}, {f})));
}

} // namespace
} // namespace magfem
