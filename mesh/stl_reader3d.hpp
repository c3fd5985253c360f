#pragma once
// A CAD part as a closed triangulated surface from an STL file (ASCII or binary), read with
// CGAL's STL reader and checked with CGAL's Polygon_mesh_processing: CGAL is already the
// mesher's library, so the part's checks and its inside/outside queries (SurfaceIndex3D) use
// the same exact predicates, and VTK stays in the VTU writer.
#include <string>

#include "mesh/geometry3d.hpp"

namespace magfem {

// Reads `path`; coordinates are multiplied by unit_m (metres per file unit: STL carries no
// unit). The result is one closed, manifold, connected, self-intersection-free surface,
// oriented outward (inconsistent or inward triangle orientations, common in exported files,
// are repaired), with `index` and `inside_point` set; `file` is `path`.
// Throws MeshError(part "", field "file", "<path>: <reason>") for an unreadable, empty or
// malformed file (including a binary file whose size contradicts its triangle count and an
// ASCII file that does not parse), degenerate triangles, boundary edges (not closed), edges of
// more than two triangles or vertices where separate sheets meet (not a manifold), several
// separate pieces, and self-intersections; the reason locates the fault in file units.
TriangleSurface read_stl_surface(const std::string& path, double unit_m);

} // namespace magfem
