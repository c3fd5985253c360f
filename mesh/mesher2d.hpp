#pragma once
// 2D mesher: CGAL's constrained Delaunay refinement (Delaunay_mesher_2) of a Geometry2D into a
// Mesh2D with a part index per triangle. CGAL stays inside mesher2d.cpp.
//
// What the mesh promises (SI metres):
// - Boundaries: every arc is cut into chords with sagitta <= chord_tolerance and chord length
//   <= the local target size (the smaller of the two sides' sizes, including the gap rule);
//   Mesh2D::quality.max_sagitta is the achieved maximum. A circle alone is cut at uniformly
//   spaced angles from angle 0; parts meeting on a circle share its vertices, and sector
//   corners on it replace the nearest uniform angle (circle_set2d.hpp). Straight edges are split
//   to the local size. CGAL may split boundary chords further (on the chord).
// - Regions: a triangle belongs to the last part whose polygonal outline contains it, else
//   region_background inside the domain disk, else region_shell. The polygons are exactly the
//   inserted constraints, so each region's area equals its polygon's area up to round-off and
//   differs from the exact area by at most (arc length * max_sagitta). Edges of parts hidden
//   under later parts are not constraints. Vertices of different parts closer than 1 % of the
//   smallest possible size are merged (touching parts, constraint_set2d.hpp).
// - Sizes: the longest edge of a triangle is at most h(centroid), where h is the region's size
//   (part max_size or default_size, times size_scale), lowered near finer neighbours and graded
//   away from them with slope 0.5 (size_field2d.hpp), and lowered by the air-gap rule
//   (gap_rule2d.hpp): at least gap_layers elements across every air gap between two different
//   parts, or a part and the domain boundary, that is wider than 3 chord tolerances (narrower
//   ones count as contact). "Air" is the background region: a part filled with air is a part,
//   sized by its max_size. h never drops below min(1, size_scale) * chord_tolerance / gap_layers.
// - Quality: minimum angle >= min(min_angle_deg, 30) degrees (CGAL is asked for 1 degree more to
//   absorb the snapping below; it proves termination up to 20.7 degrees and terminates in
//   practice up to ~33), except next to sharper input corners, crossings and tangencies.
// - Open boundary: the shell R1 <= r <= R2 = shell_ratio R1 gets the size
//   min(R1 chord length, (R2 - R1) / 4 * min(1, size_scale)), hence at least 4 layers radially;
//   the R1 circle is one constraint shared by both sides (conforming). Vertices on the outer
//   circles lie exactly on them: a vertex CGAL adds on an outer chord is moved radially onto
//   the circle (by at most the sagitta); these circles get at least 128 chords so that the
//   move tilts no angle by more than ~0.7 degrees. outer_edges are the R2 edges (open) or the R1
//   edges (dirichlet/neumann), oriented counter-clockwise (domain on the left).
// - Axisymmetric geometry (Symmetry2D::axisymmetric): the domain and the shell are the x >= 0
//   halves of the disk and ring; their sides on the axis are split by CGAL only (at the
//   refinement's needs and at part vertices on the axis, which are put exactly on x = 0), and
//   the boundary edges on the axis are axis_edges instead of outer_edges.
// - Symmetry planes (Geometry2D::planes): the domain and the shell are the quarter or half
//   disk and ring on the kept side (coordinate >= 0), the parts are cut at the planes (the
//   crossing points exactly on them), a part wholly beyond a plane has no element (its mirror
//   image stands for it), and the boundary edges on each plane are Mesh2D::symmetry_edges.
// - Triangles are counter-clockwise; quality holds the min/max angle, the min area and the max
//   sagitta. Nothing is printed.
// Throws MeshError naming the part (and field) for invalid input, a part reaching beyond the
// domain, a part with no element (covered by later parts), a mesh of more than 5 million
// vertices, or a mesh CGAL cannot build.
#include "mesh/geometry2d.hpp"
#include "mesh/mesh2d.hpp"
#include "mesh/size_field2d.hpp"

namespace magfem {

// refine_sizes (adaptive refinement, adaptive_size2d.hpp): when given, it replaces the graded
// field as the size bound of the Delaunay refinement, while the outlines are still cut to the
// case's own sizes. So every pass of an adaptive run meshes the same polygons (the geometry
// error is the chord tolerance's business, fixed by the case) and differences between passes
// are discretisation error only. CGAL still splits boundary chords (on the chord) as needed.
Mesh2D build_mesh_2d(const Geometry2D& geometry, const SizeField2D* refine_sizes = nullptr);

} // namespace magfem
