// RegionSlots (postproc/region_slots.hpp): one slot per (DOF, region), which keeps the
// recoveries from mixing materials. Three triangles in a strip, regions 5, 7 and 5, and a
// fourth skipped (a shell element): DOFs inside one region get one slot, interface DOFs one
// per region around them, a DOF only the skipped element touches none. A region asking at a
// DOF it does not touch gets -1; own_slot gives every element its own region's slot. Merged
// slots (a region's value read by another), a lost interface slot or a skipped element
// counted fail it.
#include <gtest/gtest.h>

#include <array>
#include <set>

#include "postproc/region_slots.hpp"

namespace magfem {
namespace {

TEST(RegionSlots, OneSlotPerDofAndRegionAroundIt) {
  //  DOFs 0..6; triangles (0,1,2) region 5, (1,2,3) region 7, (2,3,4) region 5,
  //  (4,5,6) skipped.
  const std::array<std::array<int, 3>, 4> triangles = {
      {{0, 1, 2}, {1, 2, 3}, {2, 3, 4}, {4, 5, 6}}};
  const std::array<int, 4> part = {5, 7, 5, RegionSlots::skip};
  const RegionSlots slots(
      7, triangles.size(), 3, [&](std::size_t t) { return triangles[t].data(); },
      [&](std::size_t t) { return part[t]; });
  const std::array<int, 7> expected_regions = {1, 2, 2, 2, 1, 0, 0};
  for (int d = 0; d < 7; ++d)
    EXPECT_EQ(slots.regions_at(d), expected_regions[d]) << "DOF " << d;
  EXPECT_EQ(slots.size(), 8u);
  EXPECT_EQ(slots.n_dofs(), 7);
  EXPECT_EQ(slots.slot(0, 7), -1);
  EXPECT_EQ(slots.slot(4, 7), -1);
  EXPECT_EQ(slots.slot(5, 5), -1);
  // Every (DOF, region) pair of an element has its own slot, and no two pairs share one.
  std::set<int> seen;
  for (std::size_t t = 0; t < 3; ++t)
    for (int d : triangles[t]) {
      const int s = slots.own_slot(d, part[t]);
      ASSERT_GE(s, 0);
      EXPECT_EQ(s, slots.slot(d, part[t]));
      EXPECT_EQ(slots.part(s), part[t]);
      EXPECT_GE(s, slots.begin(d));
      EXPECT_LT(s, slots.end(d));
      seen.insert(s);
    }
  EXPECT_EQ(seen.size(), slots.size());
  EXPECT_TRUE(RegionSlots().empty());
}

} // namespace
} // namespace magfem
