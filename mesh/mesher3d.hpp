#pragma once
// 3D mesher: Geometry3D -> conforming tetrahedral Mesh3D (TetGen for the volume; the surface
// triangulation is built here so that faces shared by adjacent parts appear exactly once).
//
// How the domain is described to TetGen: parts of the same kind and frame (spherical segments
// about one centre, coaxial cylinders, boxes with one orientation) are cut into the cells of a
// common curvilinear grid; every grid face with different labels on its two sides (part, air,
// shell, exterior) is triangulated once. Two parts claiming the same cell intersect; parts in
// different frames must neither intersect nor touch (both are rejected with a MeshError naming
// both parts).
//
// Sizes: the local size h(x) bounds the longest edge of every element near x. It is the
// minimum of the region sizes (Part3D::max_size or MeshOptions3D::default_size) of the
// regions touching a surface, the chord-tolerance size of curved part surfaces (facet sagitta
// <= chord_tolerance; the outer spheres are exempt, their nodes lie exactly on them anyway),
// gap sizes (gap width / gap_layers across thin air gaps) and probe_size within probe_size of
// each ProbeSurface, growing away from those features by a fixed grading (0.3 m per m).
// size_scale multiplies every size, the chord limit only when size_scale < 1 (coarsening never
// breaks the chord tolerance). default_size <= 0 means outer.radius / 8; chord_tolerance <= 0
// means no chord limit. Quality: TetGen radius-edge bound MeshOptions3D::radius_edge_ratio
// and a requested minimum dihedral angle of 10 deg (not always reached next to the preserved
// surface mesh; Mesh3D::quality reports what was reached).
//
// Nodes of curved surfaces lie exactly on them (the surface mesh is preserved by TetGen -Y).
// Limitations: parts of different frames may not touch (a cylinder standing on a box face, a
// rotated segment touching another array); coincident surfaces of different frames are not
// merged.
#include <functional>
#include <vector>

#include "mesh/geometry3d.hpp"
#include "mesh/mesh3d.hpp"
#include "mesh/mesh_estimate3d.hpp"
#include "mesh/tet_piece_mesh3d.hpp"

namespace magfem {

// Called with the estimated mesh size once the size field is known, before the surfaces and
// the volume are meshed; it may throw to stop the run (the memory guard). The second
// argument estimates the tetrahedra with every size multiplied by a factor (a coarser
// --mesh-scale; seconds per call on large cases).
using MeshSizeCheck =
    std::function<void(const MeshEstimate3D&, const std::function<double(double)>&)>;

// Throws MeshError naming the offending part(s) for degenerate primitives, parts outside the
// domain ball, intersecting parts and TetGen failures. `pieces`: who meshes the two pieces of
// a domain split for TetGen (domain_split3d.hpp); empty: this process, on two threads if it has
// them. The mesh is the same either way.
Mesh3D build_mesh_3d(const Geometry3D& geometry, const std::vector<ProbeSurface>& refine = {},
                     const MeshSizeCheck& check = {}, const PieceRunner3D& pieces = {});

// The estimate build_mesh_3d passes to its check, without meshing (the size field only): for a
// caller that must know the size of several meshes before it runs them at once.
// `check`, if given, is called with it as build_mesh_3d calls its own.
MeshEstimate3D estimate_geometry_mesh_3d(const Geometry3D& geometry,
                                         const std::vector<ProbeSurface>& refine = {},
                                         const MeshSizeCheck& check = {});

} // namespace magfem
