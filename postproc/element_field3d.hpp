#pragma once
// The solved 3D field at many points of one tet, its geometry gathered once: one
// TetGeometry for all the points of a straight tet (Field3D's per-point calls each compute
// their own, which made the energy summary and the recovery compute ~40 inverses per tet),
// the 10 node positions of a curved one, and the tet's potential coefficients. The
// arithmetic is Field3D's per-point arithmetic, so the values are the same bits; Field3D's
// per-point calls are this class over one point.
#include <array>
#include <cstddef>

#include <Eigen/Core>

#include "postproc/field3d.hpp"
#include "solver/tet_lagrange.hpp"

namespace magfem {

class ElementField3D {
public:
  // What one point of the tet needs: its position (m), grad phi there (the FE potential
  // plus, in total regions, the coils' source potential; A/m with a minus sign to H) and the
  // volume element relative to the barycentric measure (Field3D::volume_density).
  struct Point {
    Eigen::Vector3d x, grad_phi;
    double density = 0;
  };

  // `field` must outlive this object.
  ElementField3D(const Field3D& field, std::size_t t);

  Point at(const std::array<double, 4>& bary) const;
  // H (A/m) at point q of tet_rule(SourceFieldTable3D::rule_degree) as Field3D::H_at, the
  // point's position and volume element in `p`.
  Eigen::Vector3d H_at(int q, Point& p) const;
  // B (T) at the element's DOF node i, as Field3D::B_at_node.
  Eigen::Vector3d B_at_node(int i) const;

private:
  const Field3D& field_;
  std::size_t t_;
  bool curved_;
  int count_;                             // shape functions: 4 or 10
  TetGeometry geometry_;                  // straight tets
  std::array<Eigen::Vector3d, 4> corner_; // straight tets: the vertices
  std::array<Eigen::Vector3d, 10> node_;  // curved tets: the 10 node positions
  std::array<double, 10> value_{};        // phi (+ the source potential in total regions)
};

} // namespace magfem
