#pragma once
// 2D mesher: CGAL's constrained Delaunay refinement (Delaunay_mesher_2) of a Geometry2D into a
// Mesh2D with a part index per triangle. CGAL stays inside mesher2d.cpp.
//
// What the mesh promises (SI metres):
// - Boundaries: every arc is cut into chords at uniform angles with sagitta <= chord_tolerance
//   and chord length <= the local target size (the smaller of the two sides' sizes, including
//   the gap rule); the achieved maximum sagitta is Mesh2D::quality.max_sagitta. Straight edges
//   are split to the local size. CGAL may split boundary chords further (never off the chord).
// - Regions: a triangle belongs to the last part whose polygonal outline contains its centroid,
//   else region_background inside the domain disk, else region_shell. The polygons are exactly
//   the inserted constraints, so each region's area equals its polygon's area up to round-off
//   (and differs from the exact area by at most perimeter * max_sagitta). Parts overridden
//   where later parts lie on them keep no constraint there.
// - Sizes: the longest edge of a triangle is at most h(centroid), where h is the region's size
//   (part max_size or default_size, times size_scale), lowered near finer neighbours and graded
//   away from them with slope 0.5 (neighbouring elements differ by about 1.5x at most), and
//   lowered by the air-gap rule (see gap_rule2d.hpp): at least gap_layers elements across every
//   air gap between two different parts or between a part and the domain boundary. Sizes never
//   drop below min(1, size_scale) * chord_tolerance / gap_layers.
// - Quality: minimum angle >= min(min_angle_deg, 30) degrees except next to input corners and
//   constraint crossings sharper than that (CGAL proves termination up to 20.7 degrees; up to 30
//   it terminates in practice; 28 is the default).
// - Open boundary: the shell R1 <= r <= R2 = shell_ratio R1 is meshed with size
//   min(R1 chord length, (R2 - R1) / 4), so at least 4 layers radially; the R1 circle is one
//   constraint shared by both sides (conforming). Vertices on the outer circles lie exactly on
//   them: a vertex CGAL adds on an outer chord is moved radially onto the circle (by at most
//   the sagitta). outer_edges are the R2 edges (open) or the R1 edges (dirichlet/neumann),
//   oriented counter-clockwise (domain on the left).
// - Triangles are counter-clockwise; quality holds the min/max angle and the min area.
// Throws MeshError naming the part (and field) for invalid input, a part reaching beyond the
// domain, a part with no element (covered by later parts), a mesh of more than 5 million
// vertices, or a mesh CGAL cannot build. Prints nothing.
#include "mesh/geometry2d.hpp"
#include "mesh/mesh2d.hpp"

namespace magfem {

Mesh2D build_mesh_2d(const Geometry2D& geometry);

} // namespace magfem
