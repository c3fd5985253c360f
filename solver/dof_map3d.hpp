#pragma once
// Degrees of freedom of continuous Lagrange elements on a tetrahedral mesh: mesh vertices
// first, then (order 2) one per edge, numbered in sorted order of the edge's vertex pair.
// Also the coordinates of every DOF node (for output).
#include <array>
#include <vector>

#include <Eigen/Core>

#include "mesh/geometry3d.hpp"
#include "mesh/mesh3d.hpp"

namespace magfem {

struct SphereSurface {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0;
};

// The spheres of a geometry on which mesh faces lie: the r_inner > 0 and r_outer faces of
// every spherical segment, the domain sphere and (open boundary) the outer shell sphere.
std::vector<SphereSurface> sphere_surfaces(const Geometry3D& geometry, const Mesh3D& mesh);

class DofMap3D {
public:
  DofMap3D(const Mesh3D& mesh, int order);

  int order() const { return order_; }
  int n_dofs() const { return n_dofs_; }
  int n_vertices() const { return n_vertices_; } // DOFs 0 .. n_vertices - 1
  // Order 2: the mesh vertices at the ends of the edge whose midpoint node is DOF `dof`
  // (n_vertices <= dof < n_dofs).
  std::array<int, 2> edge_ends(int dof) const {
    const long long key = edge_keys_[static_cast<std::size_t>(dof - n_vertices_)];
    return {static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffLL)};
  }
  int dofs_per_element() const { return order_ == 1 ? 4 : 10; }
  // Global DOFs of tet t in local order (see tet_lagrange.hpp).
  const int* element_dofs(std::size_t t) const { return &element_dofs_[t * dofs_per_element()]; }
  const std::vector<Eigen::Vector3d>& dof_points() const { return points_; }
  // Order 2: moves the edge nodes of region interfaces and outer faces that lie on one of
  // the spheres onto that sphere, so that the elements touching them become isoparametric
  // (curved) and the meshed volumes match the true ones to O(h^4) instead of O(h^2). The
  // vertices must already lie on the spheres (TetGen keeps them there). Order 1: no effect.
  void curve_to_spheres(const Mesh3D& mesh, const std::vector<SphereSurface>& spheres);
  // True if tet t has a moved edge node (use tet_iso_gradients for it).
  // Edge nodes whose move would fold a tet, or nearly (det J below min_curved_jacobian_ratio
  // of the straight tet's anywhere): coarse tets thin across a sphere, whose edge node moves
  // out by the sagitta. They stay at the midpoint (that face stays flat); unchecked, such a
  // tet made the stiffness matrix indefinite and CG stopped (DIVERGED_INDEFINITE).
  static constexpr double min_curved_jacobian_ratio = 0.1;
  bool is_curved(std::size_t t) const { return !curved_.empty() && curved_[t] != 0; }
  std::size_t n_curved() const;
  std::size_t n_straightened() const { return n_straightened_; } // edge nodes kept straight

  // DOFs on the given mesh faces (vertices and, order 2, edge midpoints), sorted, unique.
  std::vector<int> dofs_on_faces(const std::vector<std::array<int, 3>>& faces) const;

private:
  void number_edges(const Mesh3D& mesh); // order 2: the edge DOFs, their keys and points
  int edge_dof(int a, int b) const;
  void mark_curved(const Mesh3D& mesh, const std::vector<char>& moved);
  double min_jacobian_ratio(std::size_t t) const; // order 2

  int order_;
  int n_dofs_ = 0;
  std::vector<int> element_dofs_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<long long> edge_keys_; // sorted; edge k has DOF n_vertices + k
  int n_vertices_ = 0;
  std::vector<char> curved_; // per tet (empty until curve_to_spheres)
  std::size_t n_straightened_ = 0;
};

} // namespace magfem
