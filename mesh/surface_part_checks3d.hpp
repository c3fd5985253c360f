#pragma once
// Checks of the TriangleSurface parts (CAD parts from STL files) before anything is meshed:
// the grid's own checks (grid_frame3d, FaceSoup3D::check_parts) do not see them, because they
// belong to no grid.
#include "mesh/face_soup3d.hpp"
#include "mesh/geometry3d.hpp"

namespace magfem {

// Throws MeshError naming the part and its file when a surface part reaches the domain ball's
// radius, or intersects, touches, contains or lies inside another part (built-in or surface).
void check_surface_parts(const Geometry3D& geometry, const FaceSoup3D& soup);

} // namespace magfem
