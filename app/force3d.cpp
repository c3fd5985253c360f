#include "app/force3d.hpp"

#include <algorithm>
#include <stdexcept>

#include "app/run3d.hpp"
#include "postproc/point_locator3d.hpp"
#include "validation/analytic_force.hpp"

namespace magfem {
namespace {
// Gauss points in theta and trapezoid points in phi. The recovered field is only C0 across
// elements, so the quadrature converges algebraically; at 96 x 192 it changes the torque of the
// compensator by < 1e-4 relative between doublings (measured), far below the mesh error.
constexpr int n_theta = 96, n_phi = 192;
} // namespace

ForceResult stress_on_sphere_3d(const Run3D& run, const Eigen::Vector3d& center, double radius,
                                const Eigen::Vector3d& torque_point) {
  const PointLocator3D locator(run.mesh);
  const auto& nodal = run.recovered_B;
  const BatchFieldFunction field = [&](const std::vector<Eigen::Vector3d>& points) {
    std::vector<Eigen::Vector3d> b(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const auto loc = locator.locate(points[i]);
      if (!loc)
        throw std::runtime_error("stress sphere point outside the mesh");
      b[i] = run.field->interpolate(nodal, loc->tet, loc->bary);
    }
    return b;
  };
  const ForceTorque ft =
      maxwell_stress_on_sphere(field, center, radius, torque_point, n_theta, n_phi);
  ForceResult r;
  r.method = "stress_sphere";
  r.force = ft.force;
  r.torque = ft.torque;
  return r;
}

double relative_difference(const ForceResult& a, const ForceResult& b) {
  const double scale =
      std::max({a.force.cwiseAbs().maxCoeff(), b.force.cwiseAbs().maxCoeff(), 1e-300});
  const double tscale =
      std::max({a.torque.cwiseAbs().maxCoeff(), b.torque.cwiseAbs().maxCoeff(), 1e-300});
  return std::max((a.force - b.force).cwiseAbs().maxCoeff() / scale,
                  (a.torque - b.torque).cwiseAbs().maxCoeff() / tscale);
}

std::vector<ForceResult> compute_forces_3d(const Run3D& run) {
  std::vector<ForceResult> out;
  for (const auto& f : run.spec.forces) {
    if (f.kind != ForceSpec::Kind::sphere)
      continue;
    ForceResult r = stress_on_sphere_3d(run, f.center, f.radius, f.torque_point);
    r.name = f.name;
    if (f.check_radius > 0) {
      const ForceResult c = stress_on_sphere_3d(run, f.center, f.check_radius, f.torque_point);
      r.checked = true;
      r.check_force = c.force;
      r.check_torque = c.torque;
      r.check_relative_difference = relative_difference(r, c);
    }
    out.push_back(r);
  }
  return out;
}

CaseSpec with_stress_sphere(CaseSpec spec, double radius, const std::string& name) {
  ForceSpec f;
  f.name = name;
  f.kind = ForceSpec::Kind::sphere;
  f.radius = radius;
  spec.forces.push_back(f);
  return spec;
}

} // namespace magfem
