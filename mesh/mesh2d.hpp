#pragma once
// Linear triangle mesh of a 2D domain with a part index per triangle. Higher-order nodes are
// created by the solver's DOF map, not here.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "mesh/symmetry_plane2d.hpp"

namespace magfem {

inline constexpr int region_background = -1; // air not covered by any part
inline constexpr int region_shell = -2;       // exterior shell of an open boundary

struct MeshQuality2D {
  double min_angle_deg = 0;
  double max_angle_deg = 0;
  double min_area = 0; // m^2
  double max_sagitta = 0; // m, largest distance between a curved boundary and its chords
};

struct Mesh2D {
  std::vector<Eigen::Vector2d> nodes;           // metres
  std::vector<std::array<int, 3>> triangles;    // counter-clockwise
  std::vector<int> triangle_part;               // Geometry2D::parts index or region_*
  std::vector<std::array<int, 2>> outer_edges;  // edges on the outermost boundary
  std::vector<std::array<int, 2>> axis_edges;   // axisymmetric: edges on the axis r = 0
  // Symmetry planes the mesh was cut at (Geometry2D::planes) and, per plane, the boundary
  // edges on it (the solver's A = 0 of a `parallel` plane sits there).
  std::vector<SymmetryPlane2D> symmetry;
  std::vector<std::vector<std::array<int, 2>>> symmetry_edges;
  double shell_inner_radius = 0;                // set when the boundary is open
  double shell_outer_radius = 0;
  MeshQuality2D quality;

  std::size_t n_nodes() const { return nodes.size(); }
  std::size_t n_triangles() const { return triangles.size(); }
};

} // namespace magfem
