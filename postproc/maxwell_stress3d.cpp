#include "postproc/maxwell_stress3d.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/constants.hpp"
#include "core/gauss_legendre.hpp"
#include "solver/coil_source3d.hpp"
#include "solver/tet_lagrange.hpp"

namespace magfem {

namespace {

constexpr int default_theta = 96;

bool is_air(const RegionPhysics3D& phys) {
  return phys.material->kind == MaterialKind::linear && phys.material->mu_r == 1.0;
}

std::string where(const Eigen::Vector3d& x) {
  std::ostringstream s;
  s << "(" << x.x() << ", " << x.y() << ", " << x.z() << ") m";
  return s.str();
}

// Volume-weighted average of the element B at every DOF over the air tets only: B jumps
// across magnet and iron surfaces (tangentially), and an average over all tets smears that
// jump into the first layer of air elements. Unlike RecoveredB3D (per region), all air regions
// (and coils, mu_r 1) are one here, and the coils' known free-space field is taken out first.
std::vector<Eigen::Vector3d> air_recovered_B(const Field3D& field) {
  const DofMap3D& dofs = field.dofs();
  const Problem3D& problem = field.problem();
  const Mesh3D& mesh = *problem.mesh;
  std::vector<Eigen::Vector3d> sum(dofs.n_dofs(), Eigen::Vector3d::Zero());
  std::vector<double> weight(dofs.n_dofs(), 0.0);
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    if (problem.is_shell(t) || !is_air(problem.physics(mesh.tet_part[t])))
      continue;
    const auto& k = mesh.tets[t];
    const double vol =
        TetGeometry::of(mesh.nodes[k[0]], mesh.nodes[k[1]], mesh.nodes[k[2]], mesh.nodes[k[3]])
            .volume;
    const int* dof = dofs.element_dofs(t);
    for (int i = 0; i < dofs.dofs_per_element(); ++i) {
      // The coils' free-space field is known exactly: recover only the rest (see B()).
      Eigen::Vector3d b = field.B(t, tet_dof_nodes[i]);
      if (const CoilSource3D* src = problem.source; src && src->active())
        b -= mu0 * src->field->H(field.point(t, tet_dof_nodes[i]));
      sum[dof[i]] += vol * b;
      weight[dof[i]] += vol;
    }
  }
  for (std::size_t i = 0; i < sum.size(); ++i)
    if (weight[i] > 0)
      sum[i] /= weight[i];
  return sum;
}

} // namespace

FieldSampler3D::FieldSampler3D(const Field3D& field, const PointLocator3D& locator,
                               FieldSampling sampling)
    : field_(field), locator_(locator), sampling_(sampling) {
  if (sampling == FieldSampling::recovered)
    recovered_ = air_recovered_B(field);
}

Eigen::Vector3d FieldSampler3D::B(const Eigen::Vector3d& x) const {
  const auto loc = locator_.locate(x);
  if (!loc)
    throw std::invalid_argument("Maxwell stress: point " + where(x) +
                                " is outside the physical domain");
  const Problem3D& problem = field_.problem();
  if (!is_air(problem.physics(problem.mesh->tet_part[loc->tet])))
    throw std::invalid_argument("Maxwell stress: point " + where(x) +
                                " is not in air (the surface must lie in air)");
  if (sampling_ == FieldSampling::element)
    return loc->b_map * field_.B(loc->tet, loc->bary);
  // The recovered field is the coils' reaction; their own field is the whole device's at x.
  Eigen::Vector3d b = loc->b_map * field_.interpolate(recovered_, loc->tet, loc->bary);
  if (const CoilSource3D* src = problem.source; src && src->active())
    b += mu0 * src->field->H(x);
  return b;
}

std::vector<Eigen::Vector3d> FieldSampler3D::B(const std::vector<Eigen::Vector3d>& xs) const {
  std::vector<Eigen::Vector3d> b(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i)
    b[i] = B(xs[i]);
  return b;
}

ForceTorque maxwell_stress_sphere_3d(const FieldSampler3D& B, const Eigen::Vector3d& center,
                                     double radius, const Eigen::Vector3d& torque_point,
                                     const StressOptions3D& options) {
  const int n_theta = options.n_theta > 0 ? options.n_theta : default_theta;
  const int n_phi = options.n_phi > 0 ? options.n_phi : 2 * n_theta;
  const std::vector<SurfacePoint> pts = sphere_quadrature(center, radius, n_theta, n_phi);
  std::vector<Eigen::Vector3d> xs(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    xs[i] = pts[i].x;
  return maxwell_stress_sum(pts, B.B(xs), torque_point);
}

std::vector<SurfacePoint> box_quadrature(const Eigen::Vector3d& center, const Eigen::Vector3d& size,
                                         int n_long) {
  const double longest = size.maxCoeff();
  std::vector<SurfacePoint> pts;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const int nu = std::max(8, static_cast<int>(std::ceil(n_long * size[u] / longest)));
    const int nv = std::max(8, static_cast<int>(std::ceil(n_long * size[v] / longest)));
    const QuadratureRule ru = gauss_legendre(nu, -0.5 * size[u], 0.5 * size[u]);
    const QuadratureRule rv = gauss_legendre(nv, -0.5 * size[v], 0.5 * size[v]);
    for (double side : {-1.0, 1.0})
      for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
          SurfacePoint p;
          p.x = center;
          p.x[axis] += side * 0.5 * size[axis];
          p.x[u] += ru.x[i];
          p.x[v] += rv.x[j];
          p.n = Eigen::Vector3d::Zero();
          p.n[axis] = side;
          p.w = ru.w[i] * rv.w[j];
          pts.push_back(p);
        }
  }
  return pts;
}

ForceTorque maxwell_stress_box_3d(const FieldSampler3D& B, const Eigen::Vector3d& center,
                                  const Eigen::Vector3d& size, const Eigen::Vector3d& torque_point,
                                  int n_long) {
  const std::vector<SurfacePoint> pts = box_quadrature(center, size, n_long);
  std::vector<Eigen::Vector3d> xs(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    xs[i] = pts[i].x;
  return maxwell_stress_sum(pts, B.B(xs), torque_point);
}

ForceComparison maxwell_stress_two_spheres_3d(const FieldSampler3D& B,
                                              const Eigen::Vector3d& center, double radius_a,
                                              double radius_b, const Eigen::Vector3d& torque_point,
                                              const StressOptions3D& options) {
  return compare_force_torque(maxwell_stress_sphere_3d(B, center, radius_a, torque_point, options),
                              maxwell_stress_sphere_3d(B, center, radius_b, torque_point, options));
}

} // namespace magfem
