#include "postproc/field3d.hpp"

#include <utility>

#include "core/constants.hpp"
#include "postproc/element_field3d.hpp"
#include "solver/coil_source3d.hpp"
#include "solver/tet_lagrange.hpp"
#include "solver/tet_quadrature.hpp"

namespace magfem {

Field3D::Field3D(const Problem3D& problem, const DofMap3D& dofs, Eigen::VectorXd phi_full)
    : problem_(problem), dofs_(dofs), phi_(std::move(phi_full)) {}

namespace {
std::array<Eigen::Vector3d, 10> node_points(const DofMap3D& dofs, std::size_t t) {
  std::array<Eigen::Vector3d, 10> x;
  for (int i = 0; i < 10; ++i)
    x[i] = dofs.dof_points()[dofs.element_dofs(t)[i]];
  return x;
}
} // namespace

Eigen::Vector3d Field3D::point(std::size_t t, const std::array<double, 4>& bary) const {
  if (dofs_.is_curved(t))
    return tet_iso_point(node_points(dofs_, t), bary);
  const auto& tet = problem_.mesh->tets[t];
  const auto& p = problem_.mesh->nodes;
  return bary[0] * p[tet[0]] + bary[1] * p[tet[1]] + bary[2] * p[tet[2]] + bary[3] * p[tet[3]];
}

double Field3D::volume_density(std::size_t t, const std::array<double, 4>& bary) const {
  if (dofs_.is_curved(t))
    return tet_iso_density(node_points(dofs_, t), bary);
  const auto& tet = problem_.mesh->tets[t];
  const auto& p = problem_.mesh->nodes;
  return TetGeometry::of(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]).volume;
}

double Field3D::potential(std::size_t t, const std::array<double, 4>& bary) const {
  std::array<double, 10> n{};
  const int count = tet_values(dofs_.order(), bary, n.data());
  const int* dof = dofs_.element_dofs(t);
  double v = 0;
  for (int i = 0; i < count; ++i)
    v += phi_[dof[i]] * n[i];
  return v;
}

Eigen::Vector3d Field3D::grad_potential(std::size_t t, const std::array<double, 4>& bary) const {
  return ElementField3D(*this, t).at(bary).grad_phi;
}

bool Field3D::adds_source(std::size_t t) const {
  const CoilSource3D* src = problem_.source;
  return src && src->active() && !src->is_total(t) && !problem_.is_shell(t);
}

Eigen::Vector3d Field3D::H(std::size_t t, const std::array<double, 4>& bary) const {
  if (adds_source(t))
    return problem_.source->field->H(point(t, bary)) - grad_potential(t, bary);
  return -grad_potential(t, bary);
}

Eigen::Vector3d Field3D::H_at(std::size_t t, int q) const {
  ElementField3D::Point p;
  return ElementField3D(*this, t).H_at(q, p);
}

Eigen::Vector3d Field3D::B_at_node(std::size_t t, int i) const {
  return ElementField3D(*this, t).B_at_node(i);
}

Eigen::Vector3d Field3D::B_at(std::size_t t, int q) const {
  ElementField3D::Point p;
  const Eigen::Vector3d h = ElementField3D(*this, t).H_at(q, p);
  return B_of_H(t, p.x, h);
}

int Field3D::shape_gradients(std::size_t t, const std::array<double, 4>& bary,
                             std::array<Eigen::Vector3d, 10>& grad, Eigen::Vector3d& x) const {
  if (dofs_.is_curved(t)) {
    tet_iso_gradients(node_points(dofs_, t), bary, grad.data(), x);
    return 10;
  }
  const auto& tet = problem_.mesh->tets[t];
  const auto& p = problem_.mesh->nodes;
  x = bary[0] * p[tet[0]] + bary[1] * p[tet[1]] + bary[2] * p[tet[2]] + bary[3] * p[tet[3]];
  return tet_gradients(dofs_.order(), TetGeometry::of(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]),
                       bary, grad.data());
}

Eigen::Vector3d Field3D::magnetization(std::size_t t, const Eigen::Vector3d& x) const {
  const auto& phys = problem_.physics(problem_.mesh->tet_part[t]);
  if (!phys.material->is_magnet())
    return Eigen::Vector3d::Zero();
  return phys.material->B_r / mu0 * phys.magnetization.unit_at(x);
}

Eigen::Vector3d Field3D::B_of_H(std::size_t t, const Eigen::Vector3d& x,
                                const Eigen::Vector3d& h) const {
  const auto& phys = problem_.physics(problem_.mesh->tet_part[t]);
  double mu = 0, dmu = 0;
  phys.material->permeability(h.squaredNorm(), mu, dmu);
  Eigen::Vector3d b = mu * h;
  if (phys.material->is_magnet())
    b += phys.material->B_r * phys.magnetization.unit_at(x);
  return b;
}

Eigen::Vector3d Field3D::B(std::size_t t, const std::array<double, 4>& bary) const {
  return B_of_H(t, point(t, bary), H(t, bary));
}

Eigen::Vector3d Field3D::interpolate(const std::vector<Eigen::Vector3d>& nodal, std::size_t t,
                                     const std::array<double, 4>& bary) const {
  std::array<double, 10> n{};
  const int count = tet_values(dofs_.order(), bary, n.data());
  const int* dof = dofs_.element_dofs(t);
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int i = 0; i < count; ++i)
    v += n[i] * nodal[dof[i]];
  return v;
}

} // namespace magfem
