#pragma once
// Symmetry planes of a 2D model (issue 36): in a planar case the lines x = 0 and y = 0 of the
// cross-section (planes of the device), in an axisymmetric case the plane z = 0 (the line
// y = z = 0 of the r-z half plane). The mesher keeps the side where the coordinate is >= 0;
// the field on the other side is the mirror image of the field on this one, with the same
// meaning as in 3D (mesh/symmetry_plane3d.hpp):
//   field: normal   (n x H = 0, field lines cross the plane at right angles): the device is
//                   its own mirror image; B(R x) = -R B(x), and the potential (A_z planar,
//                   A_phi axisymmetric) is even: nothing to impose (the natural condition);
//   field: parallel (B . n = 0, field lines run along it): the image carries the opposite
//                   sources; B(R x) = R B(x), the potential is odd: A = 0 on the plane (a
//                   Dirichlet condition; B . n is the tangential derivative of A, or of r A).
// The currents (J_z planar, J_phi axisymmetric, both normal to the cross-section) follow:
// J(R x) = J(x) under `normal` (a pair of conductors or coils carrying the same current,
// e.g. a Helmholtz pair about z = 0), J(R x) = -J(x) under `parallel` (a go-and-return pair,
// an anti-Helmholtz pair).
#include <vector>

#include <Eigen/Core>

#include "mesh/symmetry_plane3d.hpp"

namespace magfem {

struct SymmetryPlane2D {
  int axis = 1; // 0: x = 0 (planar), 1: y = 0 (planar) or z = 0 (axisymmetric), mesh frame
  SymmetryField field = SymmetryField::normal;
};

// How the field at a point of the whole device follows from the model's share:
// B(x) = b_map * B(point), A(x) = a_sign * A(point), point the image of x on the kept side
// (x itself when it lies there).
struct FoldedPoint2D {
  Eigen::Vector2d point;
  Eigen::Matrix2d b_map = Eigen::Matrix2d::Identity();
  double a_sign = 1;
};
FoldedPoint2D fold_point_2d(const std::vector<SymmetryPlane2D>& planes, const Eigen::Vector2d& x);

// The reflection about the plane in the mesh frame (diag with -1 at the axis).
Eigen::Matrix2d reflection_2d(const SymmetryPlane2D& plane);

// The whole device over the model's share: 2 per plane.
double symmetry_factor_2d(const std::vector<SymmetryPlane2D>& planes);

// A closed polyline (last vertex connects to the first) cut to the kept side of every plane
// (Sutherland-Hodgman): the points where it crosses a plane lie exactly on it. Empty when
// nothing of the loop's area is on the kept side. Edges along a plane may overlap (a concave
// loop crossing a plane several times): as mesh constraints they lie on the cut anyway.
std::vector<Eigen::Vector2d> clip_to_share(const std::vector<Eigen::Vector2d>& loop,
                                           const std::vector<SymmetryPlane2D>& planes);

// Names as the case file spells them: "x", "y" planar, "z" axisymmetric.
const char* plane_name_2d(const SymmetryPlane2D& plane, bool axisymmetric);

} // namespace magfem
