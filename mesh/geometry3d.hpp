#pragma once
// 3D geometry as the mesher and the analytic models see it: parts built from primitives in a
// local frame, placed by a rigid motion. SI metres and radians (the case reader converts).
// Spherical coordinates as in the thesis body: theta polar from +z, phi azimuth from +x.
#include <array>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "mesh/coil3d.hpp"
#include "mesh/placement3d.hpp"
#include "mesh/symmetry_plane3d.hpp"

namespace magfem {

// rho in [r_inner, r_outer], theta in [theta_min, theta_max], phi in [phi_min, phi_max] about
// the local origin. Covers solid spheres (r_inner = 0, full ranges), shells, hemispheres
// (theta_max = pi/2), caps and wedges.
struct SphericalSegment {
  double r_inner = 0, r_outer = 0;
  double theta_min = 0, theta_max = 0;
  double phi_min = 0, phi_max = 0;
};

// Local axis +z, from z = 0 (base) to z = height; r_inner = 0 for a solid cylinder.
struct Cylinder {
  double r_inner = 0, r_outer = 0;
  double height = 0;
};

// Centred on the local origin, edges along the local axes.
struct Box {
  Vec3 size = Vec3::Zero();
};

class SurfaceIndex3D; // mesh/surface_index3d.hpp

// A closed triangulated surface read from a file (an STL part), in the local frame: one
// connected, manifold, self-intersection-free shell, every triangle counter-clockwise seen
// from outside (mesh/stl_reader3d.hpp checks all of this). The mesher keeps its triangles as
// the part's boundary (it may split them, never move them).
struct TriangleSurface {
  std::string file; // as the case names it (for messages)
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  Vec3 inside_point = Vec3::Zero(); // strictly inside, near the surface (the region seed)
  // Point-in-volume and distance queries (built once, shared by copies of the part).
  std::shared_ptr<const SurfaceIndex3D> index;
};

using Shape3D = std::variant<SphericalSegment, Cylinder, Box, TriangleSurface>;

struct Part3D {
  std::string name;
  Shape3D shape;
  Placement placement;
  double max_size = 0; // metres; 0 = MeshOptions3D::default_size
  std::string group;   // rigid group for sweeps ("" = none)
  // Air (mu_r 1, no magnetization): a refinement region. The field is smooth across a layer of
  // air between it and another part, so such a layer is not a gap the mesh must resolve.
  bool air = false;
};

enum class OuterKind3D { open, dirichlet, neumann };

// Computational domain: the ball of `radius` about the origin. For `open`, a spherical shell
// from radius to shell_ratio * radius is added and mapped to infinity by the solver.
struct OuterBoundary3D {
  OuterKind3D kind = OuterKind3D::open;
  double radius = 0;
  double shell_ratio = 1.5;
};

// A target element size (m) at a point: adaptive refinement (pipeline/adapt3d.hpp).
struct SizeSample3D {
  Vec3 x = Vec3::Zero();
  double h = 0;
};

struct MeshOptions3D {
  double default_size = 0;        // metres, background air
  double chord_tolerance = 0;     // metres: max distance between a curved surface and its facets
  double radius_edge_ratio = 1.6; // TetGen quality bound (-q)
  int gap_layers = 3;             // minimum element layers across thin air gaps
  double size_scale = 1.0;        // multiplies every size (refinement studies)
  double probe_size = 0;          // metres: size near probe surfaces (0 = no refinement)
  double shell_size = 0;          // metres: max size in the open-boundary shell (0 = default_size)
  // The solver will curve the elements onto spheres (order 2): a size_scale > 1 may then
  // coarsen the chord limit of spheres too (their facets are not the geometry).
  bool spheres_curved = false;
  // The solver's element order. A gap is warned about when the nodes across it, h / order
  // apart, are farther apart than it is wide: P2 elements of 1.6 mm in the compensator's 1 mm
  // gap gave its torque and force as closely as 0.8 mm ones at 4x the unknowns.
  int element_order = 1;
  // Adaptive refinement: size sources added to the field the mesher builds (graded like its
  // own, combined by the minimum, so the case's sizes, chord and gap rules stay upper bounds;
  // not multiplied by size_scale). Shared by the copies of a case; null = none.
  std::shared_ptr<const std::vector<SizeSample3D>> refine_sizes;
  // Estimated tetrahedra from which the mesher may cut the domain in two and mesh the pieces
  // at once (mesh/domain_split3d.hpp). Below it (most tests) the mesh is one TetGen call's;
  // tests lower it to split small meshes. Not a case-file setting.
  double split_min_tetrahedra = 400e3;
};

struct Geometry3D {
  std::vector<Part3D> parts;
  std::vector<Coil3D> coils; // not meshed: they enter through their source field
  OuterBoundary3D outer;
  MeshOptions3D options;
  // Symmetry planes (mesh/symmetry_plane3d.hpp): only the side where each plane's coordinate
  // is >= 0 is meshed; the cut on the plane is a boundary of the mesh.
  std::vector<SymmetryPlane3D> symmetry;
};

} // namespace magfem
