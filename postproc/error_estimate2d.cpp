#include "postproc/error_estimate2d.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "solver/curl2d.hpp"
#include "solver/shell_transform.hpp"
#include "solver/triangle_lagrange.hpp"
#include "solver/triangle_quadrature.hpp"

namespace magfem {
namespace {

double area_of(const Mesh2D& mesh, std::size_t t) {
  const auto& tri = mesh.triangles[t];
  return TriangleGeometry::of(mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]).area;
}

// (B* - B_h) . (H* - H_h) at x. In the open-boundary shell, whose coordinates stand for the
// whole exterior, the energy density carries the transformation's metric (as in energy2d.cpp).
double error_density(const Field2D& field, std::size_t t, const Eigen::Vector2d& x,
                     const Eigen::Vector2d& b_star, const Eigen::Vector2d& b_h) {
  const auto& problem = field.problem();
  const Eigen::Vector2d d = b_star - b_h;
  if (!problem.is_shell(t))
    return d.dot(field.H(t, x, b_star) - field.H(t, x, b_h));
  const ShellTransform shell{problem.mesh->shell_inner_radius, problem.mesh->shell_outer_radius};
  if (problem.axisymmetric())
    return nu0 * d.dot(shell.curl_metric_meridional(x) * d);
  const Eigen::Vector2d grad_a(-d.y(), d.x());
  return nu0 * grad_a.dot(shell.metric<2>(x) * grad_a);
}

// eta_K^2 of one element: B* as the recovery interpolates it in the element's own space.
double element_eta2(const PatchRecovery2D& rec, std::size_t t) {
  const Field2D& field = rec.field();
  const auto& problem = field.problem();
  const double area = area_of(*problem.mesh, t);
  double eta2 = 0;
  // Degree 4: the integrand is a polynomial of degree 2p (exact for p = 2 in linear media).
  for (const auto& q : triangle_rule(4)) {
    const Eigen::Vector2d x = field.point(t, q.bary);
    const double density = error_density(field, t, x, rec.B(t, q.bary), field.B(t, q.bary));
    eta2 += q.weight * area * measure_2d(problem.symmetry, x) * density;
  }
  return eta2;
}

} // namespace

ErrorEstimate2D estimate_error_2d(const PatchRecovery2D& rec, double energy) {
  const auto& mesh = *rec.field().problem().mesh;
  ErrorEstimate2D out;
  out.eta2.assign(mesh.n_triangles(), 0.0);
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    out.eta2[t] = element_eta2(rec, t);
    out.total_eta2 += out.eta2[t];
  }
  if (energy > 0) {
    out.energy_error_pct = 100 * 0.5 * out.total_eta2 / energy;
    out.energy_norm_error_pct = 100 * std::sqrt(0.5 * out.total_eta2 / energy);
  }
  out.degraded_patches = rec.n_degraded();
  return out;
}

} // namespace magfem
