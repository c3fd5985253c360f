#pragma once
// The cut of a plane through a straight tetrahedron: sections integrate over it
// (section_flux3d) and `magfem mesh` draws the mesh on a plane with it.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "postproc/plane_frame.hpp"

namespace magfem {

using TetPlaneCut = std::vector<Eigen::Vector2d>; // (u, v) in the plane's frame, metres

// The plane's cut through the straight tet with vertices x as a convex triangle or
// quadrilateral in (u, v), counter-clockwise; empty if the plane misses it. A vertex with
// d = 0 counts as on the + side, so a face in the plane belongs to the tet below only and
// every point of the plane is covered once.
TetPlaneCut cut_tet_by_plane(const std::array<Eigen::Vector3d, 4>& x, const PlaneFrame& frame);

} // namespace magfem
