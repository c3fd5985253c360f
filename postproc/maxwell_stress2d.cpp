#include "postproc/maxwell_stress2d.hpp"

#include <sstream>
#include <stdexcept>

#include "solver/triangle_lagrange.hpp"

namespace magfem {

namespace {

constexpr int default_points = 2048;
constexpr int default_radii = 8;

bool is_air(const RegionPhysics2D& phys) {
  return phys.material->kind == MaterialKind::linear && phys.material->mu_r == 1.0 &&
         phys.current_density == 0;
}

std::string where(const Eigen::Vector2d& x) {
  std::ostringstream s;
  s << "(" << x.x() << ", " << x.y() << ") m";
  return s.str();
}

// Area-weighted average of the element B at every DOF over the air triangles only: B jumps
// across magnet, iron and coil boundaries (tangentially), and Field2D::recovered_B, which
// averages over all triangles, smears that jump into the first layer of air elements.
std::vector<Eigen::Vector2d> air_recovered_B(const Field2D& field) {
  // Barycentric coordinates of the local DOF nodes (vertices, then edge midpoints).
  static const std::array<std::array<double, 3>, 6> local = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}}};
  const DofMap2D& dofs = field.dofs();
  const Problem2D& problem = field.problem();
  const Mesh2D& mesh = *problem.mesh;
  std::vector<Eigen::Vector2d> sum(dofs.n_dofs(), Eigen::Vector2d::Zero());
  std::vector<double> weight(dofs.n_dofs(), 0.0);
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    if (problem.is_shell(t) || !is_air(problem.physics(mesh.triangle_part[t])))
      continue;
    const auto& tri = mesh.triangles[t];
    const double area =
        TriangleGeometry::of(mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]).area;
    const int* dof = dofs.element_dofs(t);
    for (int i = 0; i < dofs.dofs_per_element(); ++i) {
      sum[dof[i]] += area * field.B(t, local[i]);
      weight[dof[i]] += area;
    }
  }
  for (std::size_t i = 0; i < sum.size(); ++i)
    if (weight[i] > 0)
      sum[i] /= weight[i];
  return sum;
}

} // namespace

FieldSampler2D::FieldSampler2D(const Field2D& field, const PointLocator2D& locator,
                               FieldSampling sampling)
    : field_(field), locator_(locator), sampling_(sampling) {
  if (sampling == FieldSampling::recovered)
    recovered_ = air_recovered_B(field);
}

Eigen::Vector2d FieldSampler2D::B(const Eigen::Vector2d& x) const {
  const auto loc = locator_.locate(x);
  if (!loc)
    throw std::invalid_argument("Maxwell stress: point " + where(x) +
                                " is outside the meshed domain");
  const Problem2D& problem = field_.problem();
  if (!is_air(problem.physics(problem.mesh->triangle_part[loc->triangle])))
    throw std::invalid_argument("Maxwell stress: point " + where(x) +
                                " is not in air (the surface must lie in air)");
  if (sampling_ == FieldSampling::element)
    return loc->b_map * field_.B(loc->triangle, loc->bary);
  std::array<double, 6> n{};
  const int count = triangle_values(field_.dofs().order(), loc->bary, n.data());
  const int* dof = field_.dofs().element_dofs(loc->triangle);
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  for (int i = 0; i < count; ++i)
    b += n[i] * recovered_[dof[i]];
  return loc->b_map * b;
}

ForceTorque maxwell_stress_circle_2d(const FieldSampler2D& B, const Eigen::Vector2d& center,
                                     double radius, const Eigen::Vector2d& torque_point,
                                     const StressOptions2D& options) {
  const int n = options.n_points > 0 ? options.n_points : default_points;
  return maxwell_stress_on_circle([&](const Eigen::Vector2d& x) { return B.B(x); }, center, radius,
                                  torque_point, n);
}

ForceTorque maxwell_stress_band_2d(const FieldSampler2D& B, const Eigen::Vector2d& center,
                                   double r_inner, double r_outer,
                                   const Eigen::Vector2d& torque_point,
                                   const StressOptions2D& options) {
  const int n = options.n_points > 0 ? options.n_points : default_points;
  const int n_r = options.n_radii > 0 ? options.n_radii : default_radii;
  return maxwell_stress_on_band([&](const Eigen::Vector2d& x) { return B.B(x); }, center, r_inner,
                                r_outer, torque_point, n_r, n);
}

ForceComparison maxwell_stress_two_circles_2d(const FieldSampler2D& B,
                                              const Eigen::Vector2d& center, double radius_a,
                                              double radius_b, const Eigen::Vector2d& torque_point,
                                              const StressOptions2D& options) {
  return compare_force_torque(maxwell_stress_circle_2d(B, center, radius_a, torque_point, options),
                              maxwell_stress_circle_2d(B, center, radius_b, torque_point, options));
}

} // namespace magfem
