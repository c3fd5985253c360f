#pragma once
// Degrees of freedom of continuous Lagrange elements on a triangle mesh: mesh vertices first,
// then (order 2) one per edge. Also the coordinates of every DOF node (for output).
#include <array>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh2d.hpp"

namespace magfem {

class DofMap2D {
public:
  DofMap2D(const Mesh2D& mesh, int order);

  int order() const { return order_; }
  int n_dofs() const { return n_dofs_; }
  int dofs_per_element() const { return order_ == 1 ? 3 : 6; }
  // Global DOFs of triangle t in local order (see triangle_lagrange.hpp).
  const int* element_dofs(std::size_t t) const { return &element_dofs_[t * dofs_per_element()]; }
  const std::vector<Eigen::Vector2d>& dof_points() const { return points_; }
  // DOFs on the given mesh edges (vertices and, order 2, edge midpoints).
  std::vector<int> dofs_on_edges(const std::vector<std::array<int, 2>>& edges) const;

private:
  int order_;
  int n_dofs_ = 0;
  std::vector<int> element_dofs_;
  std::vector<Eigen::Vector2d> points_;
  std::vector<std::pair<long long, int>> edge_index_; // sorted (key, dof) for lookups
  int edge_dof(int a, int b) const;
};

} // namespace magfem
