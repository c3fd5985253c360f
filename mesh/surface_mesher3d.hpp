#pragma once
// Triangulation of all interface faces of a GridDecomposition3D: every grid edge is divided
// once (so faces sharing it conform) following the size field, then every face is meshed in its
// chart by 2D Delaunay refinement (CGAL) without splitting its boundary.
#include <array>
#include <vector>

#include "mesh/grid_frame3d.hpp"
#include "mesh/size_field3d.hpp"

namespace magfem {

struct SurfaceMesh3D {
  std::vector<Vec3> points;                  // boundary-curve points first, shared
  std::vector<std::array<int, 3>> triangles; // unoriented
  // >= 0: an index into GridDecomposition3D::faces; symmetry_face_code(p) on symmetry plane p;
  // part_surface_tag(part) on the surface of the TriangleSurface part `part`.
  std::vector<int> triangle_face;
};

// Negative face codes: -1..-3 the (at most three) symmetry planes, below them the surface parts.
constexpr int n_symmetry_face_codes = 3;

inline int symmetry_face_code(int plane) {
  return -1 - plane;
}
inline bool is_symmetry_face(int face_code) {
  return face_code < 0 && face_code >= -n_symmetry_face_codes;
}
inline int symmetry_plane_of(int face_code) {
  return -1 - face_code; // for is_symmetry_face(face_code)
}
constexpr int part_surface_tag(int part) {
  return -1 - n_symmetry_face_codes - part;
}

// Meshes the grid's interface faces, then the triangles of geometry's TriangleSurface parts
// (which are in no grid). merge_tol: points of different curves closer than this are one point
// (metres). With symmetry planes (the faces already clipped by decompose_geometry_3d), each
// plane's share inside the ball of outer_radius is triangulated too, conforming to the curves
// where the kept faces meet it and to the lines where two planes meet.
SurfaceMesh3D mesh_surfaces_3d(const Geometry3D& geometry, const GridDecomposition3D& dec,
                               const SizeField3D& size, double merge_tol,
                               const std::vector<SymmetryPlane3D>& planes = {},
                               double outer_radius = 0);

} // namespace magfem
