#include "postproc/field2d.hpp"

#include <cmath>

#include "solver/curl2d.hpp"
#include "solver/triangle_lagrange.hpp"

namespace magfem {

Field2D::Field2D(const Problem2D& problem, const DofMap2D& dofs, Eigen::VectorXd a_full)
    : problem_(problem), dofs_(dofs), a_(std::move(a_full)) {}

Eigen::Vector2d Field2D::point(std::size_t t, const std::array<double, 3>& bary) const {
  const auto& tri = problem_.mesh->triangles[t];
  const auto& p = problem_.mesh->nodes;
  return bary[0] * p[tri[0]] + bary[1] * p[tri[1]] + bary[2] * p[tri[2]];
}

double Field2D::A(std::size_t t, const std::array<double, 3>& bary) const {
  std::array<double, 6> n{};
  const int count = triangle_values(dofs_.order(), bary, n.data());
  const int* dof = dofs_.element_dofs(t);
  double a = 0;
  for (int i = 0; i < count; ++i)
    a += a_[dof[i]] * n[i];
  return a;
}

Eigen::Vector2d Field2D::B(std::size_t t, const std::array<double, 3>& bary) const {
  const auto& tri = problem_.mesh->triangles[t];
  const auto& p = problem_.mesh->nodes;
  const auto g = TriangleGeometry::of(p[tri[0]], p[tri[1]], p[tri[2]]);
  std::array<Eigen::Vector2d, 6> grad;
  const int count = triangle_gradients(dofs_.order(), g, bary, grad.data());
  const int* dof = dofs_.element_dofs(t);
  Eigen::Vector2d grad_a = Eigen::Vector2d::Zero();
  for (int i = 0; i < count; ++i)
    grad_a += a_[dof[i]] * grad[i];
  if (!problem_.axisymmetric())
    return curl_2d(problem_.symmetry, 0.0, grad_a, point(t, bary));
  // A point interpolated onto the axis lands a hair off it, where A/r would be round-off
  // over round-off: within 1e-9 of the element size it is on the axis.
  Eigen::Vector2d x = point(t, bary);
  if (x.x() < 1e-9 * std::sqrt(2 * g.area))
    x.x() = 0;
  return curl_2d(problem_.symmetry, A(t, bary), grad_a, x);
}

Eigen::Vector2d Field2D::H(std::size_t t, const Eigen::Vector2d& x,
                           const Eigen::Vector2d& b) const {
  const auto& phys = problem_.physics(problem_.mesh->triangle_part[t]);
  Eigen::Vector2d b_eff = b;
  if (phys.material->is_magnet())
    b_eff -= phys.material->B_r * phys.magnetization.unit_at({x.x(), x.y(), 0}).head<2>();
  double nu = 0, dnu = 0;
  phys.material->reluctivity(b_eff.squaredNorm(), nu, dnu);
  return nu * b_eff;
}

std::vector<Eigen::Vector2d> Field2D::recovered_B() const {
  std::vector<Eigen::Vector2d> sum(dofs_.n_dofs(), Eigen::Vector2d::Zero());
  std::vector<double> weight(dofs_.n_dofs(), 0.0);
  // Barycentric coordinates of the local DOF nodes (vertices, then edge midpoints).
  static const std::array<std::array<double, 3>, 6> local = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}}};
  const auto& mesh = *problem_.mesh;
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    if (problem_.is_shell(t))
      continue;
    const auto& tri = mesh.triangles[t];
    const double area =
        TriangleGeometry::of(mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]).area;
    const int* dof = dofs_.element_dofs(t);
    for (int i = 0; i < dofs_.dofs_per_element(); ++i) {
      sum[dof[i]] += area * B(t, local[i]);
      weight[dof[i]] += area;
    }
  }
  for (std::size_t i = 0; i < sum.size(); ++i)
    if (weight[i] > 0)
      sum[i] /= weight[i];
  return sum;
}

} // namespace magfem
