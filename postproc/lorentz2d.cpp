#include "postproc/lorentz2d.hpp"

#include <stdexcept>

#include "solver/curl2d.hpp"
#include "solver/triangle_lagrange.hpp"
#include "solver/triangle_quadrature.hpp"

namespace magfem {

ForceTorque lorentz_force_2d(const Field2D& field, const std::vector<int>& parts,
                             const Eigen::Vector2d& torque_point) {
  const Problem2D& problem = field.problem();
  std::vector<char> selected(problem.parts.size(), 0);
  for (int p : parts) {
    if (p < 0 || static_cast<std::size_t>(p) >= problem.parts.size())
      throw std::invalid_argument("lorentz_force_2d: part index " + std::to_string(p) +
                                  " out of range");
    selected[static_cast<std::size_t>(p)] = 1;
  }
  // Degree 4 covers (x - p) x (J z x B) for B of order <= 2 elements (degree <= 2 here).
  const auto& rule = triangle_rule(4);
  const Mesh2D& mesh = *problem.mesh;
  ForceTorque ft;
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    const int part = mesh.triangle_part[t];
    if (part < 0 || !selected[static_cast<std::size_t>(part)])
      continue;
    const double j = problem.parts[static_cast<std::size_t>(part)].current_density;
    if (j == 0)
      continue;
    const auto& tri = mesh.triangles[t];
    const double area =
        TriangleGeometry::of(mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]).area;
    for (const auto& q : rule) {
      const Eigen::Vector2d b = field.B(t, q.bary);
      if (problem.axisymmetric()) {
        // J phi_hat x (B_r r_hat + B_z z_hat) = J (B_z r_hat - B_r z_hat); r_hat averages out
        // over the turn, so only F_z = -int J B_r 2 pi r dA is left (no torque).
        const Eigen::Vector2d x = field.point(t, q.bary);
        ft.force.z() -= q.weight * area * measure_2d(problem.symmetry, x) * j * b.x();
        continue;
      }
      const Eigen::Vector2d f = j * Eigen::Vector2d(-b.y(), b.x()); // J z_hat x B
      const Eigen::Vector2d r = field.point(t, q.bary) - torque_point;
      const double w = q.weight * area;
      ft.force.head<2>() += w * f;
      ft.torque.z() += w * (r.x() * f.y() - r.y() * f.x());
    }
  }
  return ft;
}

} // namespace magfem
