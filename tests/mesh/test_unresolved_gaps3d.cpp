// The mesh's warnings for air gaps it leaves unresolved (mesh/unresolved_gaps3d.hpp): a pair
// of parts says its narrowest place; a part with gaps to several others (the bounded
// benchmark's iron 1 mm outside 32 magnets once printed 32 lines) says them in one warning
// with the range of widths and the largest elements; a gap whose nodes do lie inside it is no
// warning and does not join a group.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mesh/unresolved_gaps3d.hpp"

namespace magfem {
namespace {

const std::vector<std::string> names = {"iron", "m1", "m2", "m3", "m4", "m5", "a", "b"};

UnresolvedGap gap(double width_mm, double across_mm) {
  return {width_mm * 1e-3, across_mm * 1e-3, Vec3::Zero()};
}

TEST(UnresolvedGaps3D, OnePairSaysItsGapAndWhatToDo) {
  const auto w = unresolved_gap_warnings(names, 2, 2, 2.5, {{{6, 7}, gap(1, 3)}});
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0], "the 1 mm air gap between parts 'a' and 'b' has elements of about 3 mm across "
                  "it, their nodes (order 2) farther apart than the gap is wide (gap_layers 2, "
                  "sizes scaled by 2.5 in all: the case's mesh scale times --mesh-scale): the "
                  "field in the gap is not resolved; scale the sizes by at most 4 in all, or "
                  "make the mesh size near the gap smaller");
}

TEST(UnresolvedGaps3D, APartsGapsToSeveralOthersAreOneWarning) {
  // iron's gaps to m1..m3 (one resolved: m4's elements fit twice across it) and a's to b.
  const UnresolvedGaps gaps = {{{0, 1}, gap(1.2, 3)},
                               {{0, 2}, gap(0.9, 4)},
                               {{0, 3}, gap(1.4, 3.5)},
                               {{0, 4}, gap(1, 1.5)},
                               {{6, 7}, gap(0.5, 2)}};
  const auto w = unresolved_gap_warnings(names, 2, 1, 3, gaps);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0], "the air gaps between part 'iron' and 3 other parts ('m1', 'm2' and 'm3'), "
                  "0.9 to 1.4 mm wide, have elements of up to about 4 mm across them, their "
                  "nodes (order 2) farther apart than the gaps are wide (gap_layers 1, sizes "
                  "scaled by 3 in all: the case's mesh scale times --mesh-scale): the field in "
                  "these gaps is not resolved; scale the sizes by at most 2 in all, or make the "
                  "mesh size near the gaps smaller");
  EXPECT_EQ(
      w[1].rfind("the 0.5 mm air gap between parts 'a' and 'b' has elements of about 2 mm", 0), 0u)
      << w[1];
}

TEST(UnresolvedGaps3D, ManyOthersAreNamedInPart) {
  UnresolvedGaps gaps;
  for (int m = 1; m <= 5; ++m)
    gaps[{0, m}] = gap(1, 5);
  const auto w = unresolved_gap_warnings(names, 1, 2, 8, gaps);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("part 'iron' and 5 other parts ('m1', 'm2', 'm3' and 2 more), 1 mm wide,"),
            std::string::npos)
      << w[0];
}

// The warning was once printed into a fixed buffer: a long part name must come out whole.
TEST(UnresolvedGaps3D, LongPartNamesAreSaidWhole) {
  const std::string long_name(300, 'x');
  const auto w = unresolved_gap_warnings({long_name, "y"}, 2, 2, 4, {{{0, 1}, gap(1, 3)}});
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("'" + long_name + "' and 'y'"), std::string::npos);
  EXPECT_NE(w[0].find("near the gap smaller"), std::string::npos) << w[0];
}

TEST(UnresolvedGaps3D, ResolvedGapsSayNothing) {
  EXPECT_TRUE(unresolved_gap_warnings(names, 2, 2, 1, {{{0, 1}, gap(1, 2)}}).empty());
  // Left alone by its resolved neighbour, iron's one unresolved gap is a pair's warning.
  const auto w =
      unresolved_gap_warnings(names, 2, 2, 1, {{{0, 1}, gap(1, 2)}, {{0, 2}, gap(1, 2.5)}});
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("the 1 mm air gap between parts 'iron' and 'm2'", 0), 0u) << w[0];
}

} // namespace
} // namespace magfem
