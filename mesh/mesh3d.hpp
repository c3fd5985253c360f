#pragma once
// Linear tetrahedral mesh of a 3D domain with a part index per tetrahedron, as built by
// build_mesh_3d (mesh/mesher3d.hpp). Higher-order nodes are created by the solver's DOF map.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mesh/symmetry_plane3d.hpp"

namespace magfem {

inline constexpr int region_background_3d = -1; // air not covered by any part
inline constexpr int region_shell_3d = -2;      // exterior shell of an open boundary

struct MeshQuality3D {
  double min_dihedral_deg = 0;
  double max_dihedral_deg = 0;
  double max_radius_edge = 0; // circumradius / shortest edge (regular tet: 0.612)
};

struct Mesh3D {
  std::vector<Eigen::Vector3d> nodes;          // metres
  std::vector<std::array<int, 4>> tets;        // positive orientation (det > 0)
  std::vector<int> tet_part;                   // Geometry3D::parts index or region_*_3d
  std::vector<std::array<int, 3>> outer_faces; // faces on the outermost sphere, normal outward
  double shell_inner_radius = 0;               // set when the boundary is open
  double shell_outer_radius = 0;
  // Symmetry planes the mesh was cut at (Geometry3D::symmetry) and, per plane, the boundary
  // faces lying on it (the solver's n x H = 0 constraint of a `normal` plane sits there).
  std::vector<SymmetryPlane3D> symmetry;
  std::vector<std::vector<std::array<int, 3>>> symmetry_faces;
  MeshQuality3D quality;
  std::vector<double> part_volumes; // per Geometry3D part, m^3 (sum of its tet volumes)
  // Per tet: the size the mesher asked for there (m), its size field at the centroid capped by
  // the region's size. TetGen keeps every longest edge below it and lands well below (about
  // 0.7 of it in the mean, measured on the magnetized sphere), so a refinement relative to a
  // mesh must scale the request, not the edges it produced: asking for the edges again shrank
  // every tet by that factor, about 3x the unknowns a pass where nothing was to change.
  // Empty for meshes not made by build_mesh_3d.
  std::vector<double> tet_size;
  // What the mesher could not honour but did not refuse (e.g. an air gap whose elements have
  // nodes farther apart than it is wide at a coarse --mesh-scale); the run reports them
  // (summary.json warnings).
  std::vector<std::string> warnings;
  // The sphere (radius, m, about the origin) at which the mesher cut the domain to mesh the two
  // pieces at once (mesh/domain_split3d.hpp); 0: meshed as one piece.
  double split_radius = 0;

  std::size_t n_nodes() const { return nodes.size(); }
  std::size_t n_tets() const { return tets.size(); }
};

// A sphere patch where probes will be evaluated: centre, radius (m) and the theta/phi ranges
// (rad, about the centre, theta polar from +z). build_mesh_3d keeps elements within
// MeshOptions3D::probe_size of the patch no larger than probe_size.
struct ProbeSurface {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0;
  double theta_min = 0, theta_max = 0;
  double phi_min = 0, phi_max = 0;
};

} // namespace magfem
