#include "postproc/energy2d.hpp"

#include <algorithm>
#include <array>

#include "core/constants.hpp"
#include "solver/curl2d.hpp"
#include "solver/shell_transform.hpp"
#include "solver/triangle_lagrange.hpp"
#include "solver/triangle_quadrature.hpp"

namespace magfem {
namespace {

double energy_density(const Material& m, const Eigen::Vector2d& b_eff) {
  if (m.is_nonlinear())
    return m.curve->energy_density(b_eff.norm());
  double nu = 0, dnu = 0;
  m.reluctivity(0.0, nu, dnu);
  return 0.5 * nu * b_eff.squaredNorm();
}

int slot_of(int part, std::size_t n_parts) {
  if (part >= 0)
    return part;
  return part == region_background ? static_cast<int>(n_parts) : static_cast<int>(n_parts) + 1;
}

} // namespace

EnergySummary2D summarize_energy_2d(const Field2D& field, const std::vector<std::string>& names) {
  const auto& problem = field.problem();
  const auto& mesh = *problem.mesh;
  EnergySummary2D out;
  out.regions.resize(names.size() + 2);
  for (std::size_t i = 0; i < names.size(); ++i) {
    out.regions[i].name = names[i];
    out.regions[i].part = static_cast<int>(i);
    out.regions[i].nonlinear = problem.parts[i].material->is_nonlinear();
  }
  out.regions[names.size()] = {"air", region_background, 0, 0, 0, false, {}};
  out.regions[names.size() + 1] = {"exterior (open boundary)", region_shell, 0, 0, 0, false, {}};

  const ShellTransform shell{mesh.shell_inner_radius, mesh.shell_outer_radius};
  static const std::array<std::array<double, 3>, 3> corners = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    auto& reg = out.regions[slot_of(mesh.triangle_part[t], names.size())];
    const auto& tri = mesh.triangles[t];
    const double area =
        TriangleGeometry::of(mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]).area;
    reg.area_m2 += area;
    const bool in_shell = problem.is_shell(t);
    const Material& mat = *problem.physics(mesh.triangle_part[t]).material;
    for (const auto& q : triangle_rule(4)) {
      const Eigen::Vector2d x = field.point(t, q.bary);
      const Eigen::Vector2d b = field.B(t, q.bary);
      double w = 0;
      if (in_shell && problem.axisymmetric()) {
        w = 0.5 * nu0 * b.dot(shell.curl_metric_meridional(x) * b);
      } else if (in_shell) {
        const Eigen::Vector2d grad_a(-b.y(), b.x());
        w = 0.5 * nu0 * grad_a.dot(shell.metric<2>(x) * grad_a);
      } else {
        const Eigen::Vector2d h = field.H(t, x, b);
        double nu = 0, dnu = 0;
        mat.reluctivity(0.0, nu, dnu);
        // b_eff = B - B_r m_hat; for non-magnets it is B itself.
        w = energy_density(mat, mat.is_magnet() ? Eigen::Vector2d(h / nu) : b);
      }
      reg.energy_J_per_m += q.weight * area * measure_2d(problem.symmetry, x) * w;
    }
    // B is a polynomial of degree order-1 <= 1 per element: its maximum is at a corner.
    if (!in_shell)
      for (const auto& c : corners)
        reg.peak_B_T = std::max(reg.peak_B_T, field.B(t, c).norm());
  }
  for (const auto& r : out.regions)
    out.total_J_per_m += r.energy_J_per_m;
  return out;
}

} // namespace magfem
