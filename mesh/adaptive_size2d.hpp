#pragma once
// The size field of the next adaptive pass from the target sizes of the elements of the
// current mesh (metres). Every edge of every triangle becomes a size source carrying its
// triangle's target, so a point of the old triangle K gets at most
//   target_K + grading * (distance to K's nearest edge),
// and the field grades smoothly between neighbours of different targets (size_field2d.hpp).
// Edges rather than centroids: a centroid source would leave K's corners up to half an
// element of grading above the target.
#include <vector>

#include "mesh/mesh2d.hpp"
#include "mesh/size_field2d.hpp"

namespace magfem {

// target: one size per triangle of `mesh` (> 0). floor: the smallest size the field returns.
SizeField2D adaptive_size_field(const Mesh2D& mesh, const std::vector<double>& target,
                                double floor);

// The longest edge of each triangle (the measure the mesher's size bound limits).
std::vector<double> longest_edges(const Mesh2D& mesh);

} // namespace magfem
