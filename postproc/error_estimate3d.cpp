#include "postproc/error_estimate3d.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "core/parallel_blocks.hpp"
#include "core/thread_count.hpp"
#include "postproc/element_field3d.hpp"
#include "solver/shell_transform.hpp"
#include "solver/tet_lagrange.hpp"
#include "solver/tet_quadrature.hpp"

namespace magfem {
namespace {

// Degree 5: H* is quadratic and H_h linear per straight tet (order 2), so |H* - H_h|^2 is a
// quartic; the same rule serves order 1 (a quadratic) exactly.
constexpr int rule_degree = 5;

// The estimate costs a fraction of the solve only if the 14 points of a tet share their
// work: G* from the tet's nodal values, G_h (linear on straight tets) from its corners, and
// in linear media one mu for the tet.
double element_eta2(const PatchRecovery3D& rec, std::size_t t) {
  const Field3D& field = rec.field();
  const Problem3D& problem = field.problem();
  const Material& mat = *problem.physics(problem.mesh->tet_part[t]).material;
  const int order = field.dofs().order();
  const bool curved = field.dofs().is_curved(t);
  const bool in_shell = problem.is_shell(t);
  const ShellTransform shell{problem.mesh->shell_inner_radius, problem.mesh->shell_outer_radius};
  std::array<Eigen::Vector3d, 10> g_star;
  const int n = rec.nodal_values(t, g_star);
  const std::array<Eigen::Vector3d, 4>& corner = rec.corners(t); // unused if curved
  double mu = 0, dmu = 0;
  mat.permeability(0, mu, dmu);           // linear media and magnets: the same mu at any H
  const ElementField3D element(field, t); // curved tets: the 14 points share its geometry
  const double volume = curved ? 0 : element.at({0.25, 0.25, 0.25, 0.25}).density;
  double sum = 0;
  for (const auto& q : tet_rule(rule_degree)) {
    const auto& l = q.bary;
    std::array<double, 10> shape{};
    tet_values(order, l, shape.data());
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for (int i = 0; i < n; ++i)
      g += shape[i] * g_star[i];
    // The coils' H_s (exact) cancels in H* - H_h. The law needs the total H only in
    // nonlinear iron, and iron is a total region (coil_source3d.hpp), where G_h is H_h; in
    // reduced regions (air, magnets: linear) B(h + d) - B(h) = mu d whatever h.
    ElementField3D::Point p;
    if (curved || in_shell || mat.is_nonlinear())
      p = element.at(l);
    const Eigen::Vector3d h = curved ? Eigen::Vector3d(-p.grad_phi)
                                     : Eigen::Vector3d(l[0] * corner[0] + l[1] * corner[1] +
                                                       l[2] * corner[2] + l[3] * corner[3]);
    const Eigen::Vector3d d = g - h;
    const double dv = q.weight * (curved ? p.density : volume);
    if (in_shell) {
      // The mapped exterior: the physical error J^-1 d over dV' = |det J| dV carries the
      // metric T = |det J| J^-1 J^-T, as in the shell's stiffness (assembler3d.cpp).
      sum += dv * mu0 * d.dot(shell.metric<3>(p.x) * d);
      continue;
    }
    if (!mat.is_nonlinear()) {
      sum += dv * mu * d.squaredNorm();
      continue;
    }
    sum += dv * (field.B_of_H(t, p.x, h + d) - field.B_of_H(t, p.x, h)).dot(d);
  }
  return sum;
}

} // namespace

double energy_norm_error_pct(double error_norm2_J, double energy_norm2_J) {
  const double total = energy_norm2_J + error_norm2_J;
  return total > 0 ? 100 * std::sqrt(error_norm2_J / total) : 0.0;
}

ErrorEstimate3D estimate_error_3d(const PatchRecovery3D& recovery, double energy_J, int threads) {
  const Field3D& field = recovery.field();
  const Problem3D& problem = field.problem();
  const std::size_t n = problem.mesh->n_tets();
  ErrorEstimate3D out;
  out.indicator = "zz_spr_energy"; // Zienkiewicz-Zhu, superconvergent patch recovery
  out.eta2_J.assign(n, 0.0);
  if (threads <= 0)
    threads = element_loop_threads(n);
  parallel_blocks(n, 2048, threads, [&](std::size_t, std::size_t lo, std::size_t hi) {
    for (std::size_t t = lo; t < hi; ++t)
      out.eta2_J[t] = element_eta2(recovery, t);
  });
  for (double e : out.eta2_J) // in element order: the same bits whatever the thread count
    out.error_norm2_J += e;
  out.energy_norm2_J = 2 * energy_J;
  out.energy_norm_error_pct = energy_norm_error_pct(out.error_norm2_J, out.energy_norm2_J);
  out.energy_error_pct = out.energy_norm2_J > 0 ? 100 * out.error_norm2_J / out.energy_norm2_J : 0;
  out.degraded_patches = recovery.n_degraded();
  return out;
}

} // namespace magfem
