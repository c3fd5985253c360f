#include "postproc/element_field3d.hpp"

#include "solver/coil_source3d.hpp"
#include "solver/tet_quadrature.hpp"

namespace magfem {

ElementField3D::ElementField3D(const Field3D& field, std::size_t t)
    : field_(field), t_(t), curved_(field.dofs().is_curved(t)) {
  const Problem3D& problem = field.problem();
  const DofMap3D& dofs = field.dofs();
  const int* dof = dofs.element_dofs(t);
  count_ = curved_ ? 10 : tet_dofs(dofs.order());
  if (curved_) {
    for (int i = 0; i < 10; ++i)
      node_[i] = dofs.dof_points()[dof[i]];
  } else {
    const auto& tet = problem.mesh->tets[t];
    for (int i = 0; i < 4; ++i)
      corner_[i] = problem.mesh->nodes[tet[i]];
    geometry_ = TetGeometry::of(corner_[0], corner_[1], corner_[2], corner_[3]);
  }
  const CoilSource3D* src = problem.source;
  const bool total = src && src->active() && src->is_total(t);
  for (int i = 0; i < count_; ++i)
    value_[i] = field.phi()[dof[i]] + (total ? src->offset[dof[i]] : 0.0);
}

ElementField3D::Point ElementField3D::at(const std::array<double, 4>& bary) const {
  Point p;
  std::array<Eigen::Vector3d, 10> grad;
  if (curved_) {
    p.density = tet_iso_gradients(node_, bary, grad.data(), p.x);
  } else {
    tet_gradients(field_.dofs().order(), geometry_, bary, grad.data());
    p.x = bary[0] * corner_[0] + bary[1] * corner_[1] + bary[2] * corner_[2] + bary[3] * corner_[3];
    p.density = geometry_.volume;
  }
  p.grad_phi.setZero();
  for (int i = 0; i < count_; ++i)
    p.grad_phi += value_[i] * grad[i];
  return p;
}

Eigen::Vector3d ElementField3D::H_at(int q, Point& p) const {
  p = at(tet_rule(SourceFieldTable3D::rule_degree)[q].bary);
  if (field_.adds_source(t_))
    return field_.problem().source->table.H(t_, q) - p.grad_phi;
  return -p.grad_phi;
}

Eigen::Vector3d ElementField3D::B_at_node(int i) const {
  const Point p = at(tet_dof_nodes[i]);
  Eigen::Vector3d h = -p.grad_phi;
  if (field_.adds_source(t_))
    h += field_.problem().source->table.H_at_dof(field_.dofs().element_dofs(t_)[i]);
  return field_.B_of_H(t_, p.x, h);
}

} // namespace magfem
