#pragma once
// Rays from the surface parts (TriangleSurface, in no grid) to the nearest other part across
// the air: the widths the gap rule of the mesher resolves (mesher3d.hpp). Built-in parts are
// met on the coarse triangles of FaceSoup3D, surface parts on their own triangles.
#include <memory>

#include "mesh/face_soup3d.hpp"
#include "mesh/geometry3d.hpp"
#include "mesh/grid_frame3d.hpp"

namespace magfem {

class SurfacePartRays3D {
public:
  SurfacePartRays3D(const Geometry3D& geometry, const GridDecomposition3D& dec,
                    const FaceSoup3D& soup);
  ~SurfacePartRays3D();
  SurfacePartRays3D(const SurfacePartRays3D&) = delete;
  SurfacePartRays3D& operator=(const SurfacePartRays3D&) = delete;

  // Distance from origin along the unit direction to the first face of a part other than
  // `self` and not an air part, at least min_distance away and met within about 78 deg of its
  // normal (grazing hits are no gap); infinity when none.
  double gap(int self, const Vec3& origin, const Vec3& direction, double min_distance) const;

private:
  struct Tree;
  const Geometry3D& geo_;
  const GridDecomposition3D& dec_;
  const FaceSoup3D& soup_;
  std::unique_ptr<Tree> tree_;
};

} // namespace magfem
