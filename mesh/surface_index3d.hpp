#pragma once
// Inside/outside and distance queries on a closed triangulated surface (TriangleSurface), in
// the surface's own coordinates: CGAL's AABB tree and Side_of_triangle_mesh, built once at
// construction so that concurrent queries (sweep positions meshed on several threads) only
// read.
#include <array>
#include <memory>
#include <vector>

#include "mesh/placement3d.hpp"

namespace magfem {

class SurfaceIndex3D {
public:
  // points/triangles: a closed, oriented, manifold surface (not checked here).
  SurfaceIndex3D(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles);
  ~SurfaceIndex3D();
  SurfaceIndex3D(const SurfaceIndex3D&) = delete;
  SurfaceIndex3D& operator=(const SurfaceIndex3D&) = delete;

  // True when x lies in the enclosed volume grown by tol (metres; a negative tol asks for
  // points at least -tol inside).
  bool contains(const Vec3& x, double tol) const;
  double distance(const Vec3& x) const; // to the surface, metres

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace magfem
