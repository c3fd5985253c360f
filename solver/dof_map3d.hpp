#pragma once
// Degrees of freedom of continuous Lagrange elements on a tetrahedral mesh: mesh vertices
// first, then (order 2) one per edge, numbered in sorted order of the edge's vertex pair.
// Also the coordinates of every DOF node (for output).
#include <array>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh3d.hpp"

namespace magfem {

class DofMap3D {
public:
  DofMap3D(const Mesh3D& mesh, int order);

  int order() const { return order_; }
  int n_dofs() const { return n_dofs_; }
  int dofs_per_element() const { return order_ == 1 ? 4 : 10; }
  // Global DOFs of tet t in local order (see tet_lagrange.hpp).
  const int* element_dofs(std::size_t t) const { return &element_dofs_[t * dofs_per_element()]; }
  const std::vector<Eigen::Vector3d>& dof_points() const { return points_; }
  // DOFs on the given mesh faces (vertices and, order 2, edge midpoints), sorted, unique.
  std::vector<int> dofs_on_faces(const std::vector<std::array<int, 3>>& faces) const;

private:
  int edge_dof(int a, int b) const;

  int order_;
  int n_dofs_ = 0;
  std::vector<int> element_dofs_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<long long> edge_keys_; // sorted; edge k has DOF n_vertices + k
  int n_vertices_ = 0;
};

} // namespace magfem
