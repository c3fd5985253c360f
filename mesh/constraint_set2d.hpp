#pragma once
// The constraint graph handed to CGAL, cleaned of near-coincidences between parts. Outlines of
// different parts that touch (a disk resting on a rectangle, two tangent disks) have vertices a
// hair apart, or a vertex a hair off the other part's edge; CGAL would resolve those
// femtometre-scale features with a cascade of tiny elements. So:
//   - vertices closer than `merge` become one vertex (the first one inserted),
//   - a vertex within `merge` of an edge it is not an end of splits that edge,
//   - repeated edges are kept once.
#include <array>
#include <vector>

#include "mesh/geometry2d.hpp"

namespace magfem {

struct ConstraintSet2D {
  std::vector<Vec2> points;
  std::vector<std::array<int, 2>> segments; // indices into points
};

// loops: closed polylines (last vertex connects to the first). merge: metres.
ConstraintSet2D build_constraint_set(const std::vector<std::vector<Vec2>>& loops, double merge);

} // namespace magfem
