#include "solver/assembler2d.hpp"

#include <array>

#include "core/constants.hpp"
#include "solver/curl2d.hpp"
#include "solver/triangle_lagrange.hpp"
#include "solver/triangle_quadrature.hpp"

namespace magfem {
namespace {

std::vector<int> constrained_dofs(const Problem2D& problem, const DofMap2D& dofs) {
  std::vector<int> fixed;
  const Mesh2D& mesh = *problem.mesh;
  // A_phi vanishes on the axis (and gauges the Neumann problem there).
  if (problem.axisymmetric())
    fixed = dofs.dofs_on_edges(mesh.axis_edges);
  // A symmetry plane with `field: parallel` (B . n = 0) holds A = 0: B . n is the derivative
  // of A (planar) or r A_phi (axisymmetric) along the plane, and A is odd about it (the image
  // carries the opposite sources), so the constant is 0. `field: normal` (n x H = 0) is the
  // natural condition of the weak form: nothing to impose (mesh/symmetry_plane2d.hpp).
  for (std::size_t p = 0; p < mesh.symmetry.size(); ++p)
    if (mesh.symmetry[p].field == SymmetryField::parallel) {
      const auto on_plane = dofs.dofs_on_edges(mesh.symmetry_edges[p]);
      fixed.insert(fixed.end(), on_plane.begin(), on_plane.end());
    }
  if (problem.boundary != OuterKind::neumann) {
    const auto outer = dofs.dofs_on_edges(problem.mesh->outer_edges);
    fixed.insert(fixed.end(), outer.begin(), outer.end());
  } else if (fixed.empty()) {
    fixed = {0}; // gauge: A is defined up to a constant
  }
  return fixed;
}

bool problem_is_linear(const Problem2D& problem) {
  for (const auto& p : problem.parts)
    if (p.material->is_nonlinear()) return false;
  return !problem.air.material->is_nonlinear();
}

std::vector<int> number_equations(int n_dofs, const std::vector<int>& constrained, int& n_eqs) {
  std::vector<int> map(n_dofs, 0);
  for (int d : constrained) map[d] = -1;
  n_eqs = 0;
  for (int& m : map)
    if (m == 0) m = n_eqs++;
  return map;
}

} // namespace

Assembler2D::Assembler2D(const Problem2D& problem, const DofMap2D& dofs)
    : problem_(problem), dofs_(dofs),
      shell_{problem.mesh->shell_inner_radius, problem.mesh->shell_outer_radius},
      dof_to_eq_(number_equations(dofs.n_dofs(), constrained_dofs(problem, dofs), n_eqs_)),
      element_eqs_([&] {
        std::vector<int> eqs(problem.mesh->n_triangles() * dofs.dofs_per_element());
        for (std::size_t t = 0; t < problem.mesh->n_triangles(); ++t)
          for (int i = 0; i < dofs.dofs_per_element(); ++i)
            eqs[t * dofs.dofs_per_element() + i] = dof_to_eq_[dofs.element_dofs(t)[i]];
        return eqs;
      }()),
      linear_(problem_is_linear(problem)),
      pattern_(n_eqs_, element_eqs_, dofs.dofs_per_element()) {
  load_norm_ = compute_load_norm();
}

Eigen::VectorXd Assembler2D::expand(const Eigen::VectorXd& u) const {
  Eigen::VectorXd a = Eigen::VectorXd::Zero(dofs_.n_dofs());
  for (int d = 0; d < dofs_.n_dofs(); ++d)
    if (dof_to_eq_[d] >= 0) a[d] = u[dof_to_eq_[d]];
  return a;
}

double Assembler2D::compute_load_norm() const {
  // The residual at u = 0 is minus the external load (currents and remanence).
  Eigen::VectorXd r;
  evaluate(Eigen::VectorXd::Zero(n_eqs_), r, nullptr, TangentKind::newton);
  return r.norm();
}

void Assembler2D::element(std::size_t t, const Eigen::VectorXd& a_full, double* re, double* ke,
                          TangentKind kind, bool want_matrix) const {
  const auto& tri = problem_.mesh->triangles[t];
  const auto& nodes = problem_.mesh->nodes;
  const auto g = TriangleGeometry::of(nodes[tri[0]], nodes[tri[1]], nodes[tri[2]]);
  const int order = dofs_.order();
  const int n = dofs_.dofs_per_element();
  const int* dof = dofs_.element_dofs(t);
  const bool in_shell = problem_.is_shell(t);
  const bool axi = problem_.axisymmetric();
  const RegionPhysics2D& phys = problem_.physics(problem_.mesh->triangle_part[t]);
  const Material& mat = *phys.material;
  const bool has_source = phys.current_density != 0 || mat.is_magnet();
  // Shape-gradient products are degree 2(order-1); nonlinear laws, the shell metric, the
  // current load (degree `order`) and the axisymmetric weight r and A/r need more points than
  // a linear planar stiffness alone.
  const int degree = (in_shell || axi || mat.is_nonlinear()) ? 4 : std::max(2 * (order - 1), order);

  std::fill(re, re + n, 0.0);
  if (want_matrix) std::fill(ke, ke + n * n, 0.0);
  std::array<Eigen::Vector2d, 6> grad, c;
  std::array<double, 6> val{};
  for (const auto& q : triangle_rule(degree)) {
    triangle_gradients(order, g, q.bary, grad.data());
    Eigen::Vector2d x = Eigen::Vector2d::Zero();
    for (int k = 0; k < 3; ++k) x += q.bary[k] * nodes[tri[k]];
    const double w = q.weight * g.area * measure_2d(problem_.symmetry, x);
    if (axi || has_source)
      triangle_values(order, q.bary, val.data());
    for (int i = 0; i < n; ++i)
      c[i] = curl_2d(problem_.symmetry, val[i], grad[i], x);
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    for (int i = 0; i < n; ++i)
      b += a_full[dof[i]] * c[i];
    if (in_shell) {
      // Linear air with the shell metric: r_i = curl N_i . M B.
      const Eigen::Matrix2d m = nu0 * shell_metric(x);
      const Eigen::Vector2d flux = m * b;
      for (int i = 0; i < n; ++i)
        re[i] += w * c[i].dot(flux);
      if (want_matrix)
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j)
            ke[i * n + j] += w * c[i].dot(m * c[j]);
      continue;
    }
    Eigen::Vector2d b_eff = b;
    if (mat.is_magnet()) b_eff -= mat.B_r * phys.magnetization.unit_at({x.x(), x.y(), 0}).head<2>();
    double nu = 0, dnu = 0;
    mat.reluctivity(b_eff.squaredNorm(), nu, dnu);
    const Eigen::Vector2d h = nu * b_eff;
    for (int i = 0; i < n; ++i) re[i] += w * (h.dot(c[i]) - phys.current_density * val[i]);
    if (!want_matrix) continue;
    Eigen::Matrix2d d = nu * Eigen::Matrix2d::Identity();
    if (kind == TangentKind::newton && dnu != 0) d += 2 * dnu * b_eff * b_eff.transpose();
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d dc = d * c[i];
      for (int j = 0; j < n; ++j) ke[i * n + j] += w * dc.dot(c[j]);
    }
  }
}

Eigen::Matrix2d Assembler2D::shell_metric(const Eigen::Vector2d& x) const {
  if (problem_.axisymmetric())
    return shell_.curl_metric_meridional(x);
  // Planar: the metric acts on grad A; B = R grad A with R the rotation by -90 degrees.
  Eigen::Matrix2d rot;
  rot << 0, 1, -1, 0;
  return rot * shell_.metric<2>(x) * rot.transpose();
}

void Assembler2D::evaluate(const Eigen::VectorXd& u, Eigen::VectorXd& residual,
                           Eigen::SparseMatrix<double>* matrix, TangentKind kind) const {
  evaluate_full(expand(u), residual, matrix, kind);
}

void Assembler2D::evaluate_full(const Eigen::VectorXd& a_full, Eigen::VectorXd& residual,
                                Eigen::SparseMatrix<double>* matrix, TangentKind kind) const {
  residual = Eigen::VectorXd::Zero(n_eqs_);
  if (matrix) *matrix = pattern_.zero_matrix();
  const int n = dofs_.dofs_per_element();
  std::array<double, 6> re{};
  std::array<double, 36> ke{};
  for (std::size_t t = 0; t < problem_.mesh->n_triangles(); ++t) {
    element(t, a_full, re.data(), ke.data(), kind, matrix != nullptr);
    const int* eq = &element_eqs_[t * n];
    for (int i = 0; i < n; ++i)
      if (eq[i] >= 0) residual[eq[i]] += re[i];
    if (matrix) pattern_.add(*matrix, t, ke.data());
  }
}

} // namespace magfem
