// A sweep's mesh warnings, once per kind with the positions they apply to
// (studies/position_mesh_warnings.hpp): the grouping itself, and an FE sweep of the
// compensator whose every position has the same unresolved-gap warning with slightly different
// figures, said once in sweep_warnings and never by the positions' solves.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "studies/position_mesh_warnings.hpp"
#include "studies/sweep.hpp"
#include "tests/case_helpers.hpp"

namespace magfem {
namespace {

using Positions = std::vector<std::pair<double, std::vector<std::string>>>;

TEST(PositionMeshWarnings, OneLinePerKindWithThePositionsItAppliesTo) {
  const Positions positions = {
      {0, {"the 0.954 mm air gap between parts 'a' and 'b' is not resolved", "part 'c' is thin"}},
      {45, {}},
      {90, {"the 0.943 mm air gap between parts 'a' and 'b' is not resolved"}},
      {135, {"part 'c' is thin"}}};
  const auto w = grouped_mesh_warnings("angle_deg", positions);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0], "angle_deg 0, 90 (2 of 4 positions; the figures are those at 0): the 0.954 mm "
                  "air gap between parts 'a' and 'b' is not resolved");
  EXPECT_EQ(w[1], "angle_deg 0, 135 (2 of 4 positions): part 'c' is thin");
}

TEST(PositionMeshWarnings, ManyPositionsAreARangeAndNoWarningsNoLine) {
  Positions positions;
  for (int i = 0; i < 8; ++i)
    positions.push_back({-2.5 + i, {"gap too coarse"}});
  const auto w = grouped_mesh_warnings("position_mm", positions);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0], "position_mm -2.5 ... 4.5 (8 of 8 positions): gap too coarse");
  EXPECT_TRUE(grouped_mesh_warnings("angle_deg", {{0, {}}, {10, {}}}).empty());
}

// examples/3d/compensator_table42.yaml at --mesh-scale 2: the 1 mm gap between the magnets is
// too thin for its elements at 0 and 90 deg (gap widths 0.954 and 0.943 mm: the rotated
// outer magnet's facets lie differently). Two positions, ~11 s.
TEST(PositionMeshWarnings, AnFeSweepSaysTheGapWarningOnceForAllPositions) {
  const auto spec = read_case(test::example("3d/compensator_table42.yaml"));
  SweepOptions o;
  o.group = "outer";
  o.axis = Eigen::Vector3d::UnitY();
  o.angles_deg = {0, 90};
  o.mesh_scale = 2;
  o.jobs = 1;
  testing::internal::CaptureStderr();
  const auto rows = run_sweep(spec, o);
  const std::string said = testing::internal::GetCapturedStderr();
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& r : rows) {
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(r.mesh_warnings.size(), 1u) << r.angle_deg;
    EXPECT_NE(r.mesh_warnings[0].find("air gap between parts 'inner' and 'outer'"),
              std::string::npos);
  }
  EXPECT_EQ(said.find("air gap"), std::string::npos) << said; // not once per position
  const auto w = sweep_warnings(rows, o);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("angle_deg 0, 90 (2 of 2 positions", 0), 0u) << w[0];
  EXPECT_NE(w[0].find(rows[0].mesh_warnings[0]), std::string::npos) << w[0];
}

} // namespace
} // namespace magfem
