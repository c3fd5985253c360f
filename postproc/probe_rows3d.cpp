#include "postproc/probe_rows3d.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "postproc/probes3d.hpp"

namespace magfem {

ProbeTable tabulate_probe_3d(const ProbeSpec& probe, const std::vector<Eigen::Vector3d>& points,
                             const std::vector<Eigen::Vector3d>& B, double length_unit) {
  ProbeTable t;
  t.name = probe.name;
  if (probe.kind == ProbeSpec::Kind::plane) {
    t.columns = {"u", "v", "x", "y", "z", "Bx", "By", "Bz", "Bn"};
    const std::vector<Eigen::Vector2d> uv = plane_probe_coordinates(probe);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d x = points[i] / length_unit;
      const Eigen::Vector2d w = uv[i] / length_unit;
      t.rows.push_back({w.x(), w.y(), x.x(), x.y(), x.z(), B[i].x(), B[i].y(), B[i].z(),
                        B[i].dot(probe.plane.n)});
    }
    return t;
  }
  if (probe.kind != ProbeSpec::Kind::sphere) {
    t.columns = {"x", "y", "z", "Bx", "By", "Bz"};
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d x = points[i] / length_unit;
      t.rows.push_back({x.x(), x.y(), x.z(), B[i].x(), B[i].y(), B[i].z()});
    }
    return t;
  }
  t.columns = {"theta_deg", "phi_deg", "x", "y", "z", "Bx", "By", "Bz", "Brho", "Btheta", "Bphi"};
  for (std::size_t i = 0; i < points.size(); ++i) {
    // Angles from the sample grid (exact), not from atan2 of rounded coordinates.
    const int it = static_cast<int>(i) / probe.phi_steps, ip = static_cast<int>(i) % probe.phi_steps;
    const double th = probe.theta_steps == 1 ? probe.theta_min
                                              : probe.theta_min + it * (probe.theta_max - probe.theta_min) / (probe.theta_steps - 1);
    const double ph = probe.phi_steps == 1 ? probe.phi_min
                                            : probe.phi_min + ip * (probe.phi_max - probe.phi_min) / (probe.phi_steps - 1);
    const Eigen::Vector3d e_rho(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
    const Eigen::Vector3d e_theta(std::cos(th) * std::cos(ph), std::cos(th) * std::sin(ph), -std::sin(th));
    const Eigen::Vector3d e_phi(-std::sin(ph), std::cos(ph), 0.0);
    const Eigen::Vector3d x = points[i] / length_unit;
    const Eigen::Vector3d& b = B[i];
    t.rows.push_back({th * rad_to_deg, ph * rad_to_deg, x.x(), x.y(), x.z(), b.x(), b.y(), b.z(),
                      b.dot(e_rho), b.dot(e_theta), b.dot(e_phi)});
  }
  return t;
}

} // namespace magfem
