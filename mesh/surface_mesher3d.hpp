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
  // Index into GridDecomposition3D::faces, or part_surface_tag(p) for a triangle of the
  // TriangleSurface part p.
  std::vector<int> triangle_face;
};

constexpr int part_surface_tag(int part) {
  return -1 - part;
}

// Meshes the grid's interface faces, then the triangles of geometry's TriangleSurface parts
// (which are in no grid). merge_tol: points of different curves closer than this are one point
// (metres).
SurfaceMesh3D mesh_surfaces_3d(const Geometry3D& geometry, const GridDecomposition3D& dec,
                               const SizeField3D& size, double merge_tol);

} // namespace magfem
