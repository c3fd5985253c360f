// Overlap of placed parts for the paths that never mesh (analytic models, analytic sweeps):
// parts that only touch (a segment array, hemispheres of one ball, nested shells, stacked
// boxes) never count; parts that share volume are found with a point inside both.
#include <gtest/gtest.h>

#include <numbers>

#include "mesh/grid_frame3d.hpp"
#include "mesh/part_overlap3d.hpp"

namespace magfem {
namespace {

constexpr double pi = std::numbers::pi;

Part3D part(Shape3D shape, Vec3 translation = Vec3::Zero()) {
  Part3D p;
  p.shape = shape;
  p.placement.translation = translation;
  return p;
}

bool overlap(const Part3D& a, const Part3D& b) {
  return overlap_point(a, b).has_value() || overlap_point(b, a).has_value();
}

TEST(PartOverlap3D, TouchingPartsDoNotOverlap) {
  const auto north = part(SphericalSegment{0, 0.01, 0, pi / 2, 0, 2 * pi});
  const auto south = part(SphericalSegment{0, 0.01, pi / 2, pi, 0, 2 * pi});
  EXPECT_FALSE(overlap(north, south));
  const auto inner = part(SphericalSegment{0.005, 0.01, 0, pi, 0, 2 * pi});
  const auto outer = part(SphericalSegment{0.01, 0.02, 0, pi, 0, 2 * pi});
  EXPECT_FALSE(overlap(inner, outer));
  // Neighbours of a segment array: 45-degree wedges.
  const auto w1 = part(SphericalSegment{0.01, 0.02, 0, pi / 4, 0, pi / 4});
  const auto w2 = part(SphericalSegment{0.01, 0.02, 0, pi / 4, pi / 4, pi / 2});
  EXPECT_FALSE(overlap(w1, w2));
  const auto box1 = part(Box{Vec3(0.01, 0.01, 0.01)});
  const auto box2 = part(Box{Vec3(0.01, 0.01, 0.01)}, Vec3(0, 0, 0.01));
  EXPECT_FALSE(overlap(box1, box2));
  const auto can = part(Cylinder{0.0, 0.005, 0.01}, Vec3(0, 0, 0.005)); // on top of box1
  EXPECT_FALSE(overlap(box1, can));
}

TEST(PartOverlap3D, SharedVolumeIsFoundWithAWitnessInsideBoth) {
  const auto ball = part(SphericalSegment{0, 0.005, 0, pi, 0, 2 * pi});
  const auto near = part(SphericalSegment{0, 0.004, 0, pi, 0, 2 * pi}, Vec3(0, 0, 0.0085));
  const auto x = overlap_point(ball, near);
  ASSERT_TRUE(x.has_value()); // 0.5 mm of shared depth
  EXPECT_TRUE(part_contains(ball, *x, 0) && part_contains(near, *x, 0));
  const auto apart = part(SphericalSegment{0, 0.004, 0, pi, 0, 2 * pi}, Vec3(0, 0, 0.0095));
  EXPECT_FALSE(overlap(ball, apart));
  // A small box inside a large cylinder: found from either side.
  const auto big = part(Cylinder{0.0, 0.02, 0.02});
  const auto small = part(Box{Vec3(0.002, 0.002, 0.002)}, Vec3(0.01, 0, 0.01));
  EXPECT_TRUE(overlap(big, small));
  // Wedges of one array that overlap by 5 degrees.
  const auto w1 = part(SphericalSegment{0.01, 0.02, 0, pi / 4, 0, pi / 4});
  const auto w2 = part(SphericalSegment{0.01, 0.02, 0, pi / 4, pi / 4 - pi / 36, pi / 2});
  EXPECT_TRUE(overlap(w1, w2));
}

} // namespace
} // namespace magfem
