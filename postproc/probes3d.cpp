#include "postproc/probes3d.hpp"

#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"

namespace magfem {
namespace {

double sample(double lo, double hi, int i, int n) {
  return n <= 1 ? lo : lo + (hi - lo) * static_cast<double>(i) / (n - 1);
}

struct SpherePoint {
  double theta, phi;
  Eigen::Vector3d e_rho, e_theta, e_phi;
};

SpherePoint sphere_point(double theta, double phi) {
  const double st = std::sin(theta), ct = std::cos(theta), sp = std::sin(phi), cp = std::cos(phi);
  return {theta, phi, {st * cp, st * sp, ct}, {ct * cp, ct * sp, -st}, {-sp, cp, 0}};
}

std::vector<SpherePoint> sphere_samples(const ProbeSpec& p) {
  std::vector<SpherePoint> out;
  for (int i = 0; i < p.theta_steps; ++i)
    for (int j = 0; j < p.phi_steps; ++j)
      out.push_back(sphere_point(sample(p.theta_min, p.theta_max, i, p.theta_steps),
                                 sample(p.phi_min, p.phi_max, j, p.phi_steps)));
  return out;
}

} // namespace

std::vector<Eigen::Vector2d> plane_probe_coordinates(const ProbeSpec& p) {
  std::vector<Eigen::Vector2d> out;
  for (int i = 0; i < p.u_steps; ++i)
    for (int j = 0; j < p.v_steps; ++j)
      out.emplace_back(p.u_steps == 1 ? 0.0 : sample(-p.size_u / 2, p.size_u / 2, i, p.u_steps),
                       p.v_steps == 1 ? 0.0 : sample(-p.size_v / 2, p.size_v / 2, j, p.v_steps));
  return out;
}

std::vector<Eigen::Vector3d> probe_points_3d(const ProbeSpec& probe) {
  std::vector<Eigen::Vector3d> pts;
  switch (probe.kind) {
  case ProbeSpec::Kind::line:
    for (int i = 0; i < probe.points; ++i)
      pts.push_back(probe.start + sample(0, 1, i, probe.points) * (probe.end - probe.start));
    break;
  case ProbeSpec::Kind::points:
    pts = probe.point_list;
    break;
  case ProbeSpec::Kind::sphere:
    for (const auto& s : sphere_samples(probe))
      pts.push_back(probe.center + probe.radius * s.e_rho);
    break;
  case ProbeSpec::Kind::plane:
    for (const auto& uv : plane_probe_coordinates(probe))
      pts.push_back(probe.plane.at(uv.x(), uv.y()));
    break;
  case ProbeSpec::Kind::circle:
    throw std::invalid_argument("probe '" + probe.name + "': circle probes are 2D only");
  }
  return pts;
}

namespace {

// B_at(tet, bary): the field the probe reads (see the header).
template <class BAt>
ProbeTable sample_probe(const Field3D& field, const PointLocator3D& locator, const ProbeSpec& probe,
                        double length_unit, const BAt& B_at) {
  const std::vector<Eigen::Vector3d> pts = probe_points_3d(probe);
  ProbeTable table;
  table.name = probe.name;
  const bool sphere = probe.kind == ProbeSpec::Kind::sphere;
  const bool plane = probe.kind == ProbeSpec::Kind::plane;
  if (sphere)
    table.columns = {"theta_deg", "phi_deg", "x",    "y",      "z",    "Bx",
                     "By",        "Bz",      "Brho", "Btheta", "Bphi", "region_id"};
  else if (plane)
    table.columns = {"u", "v", "x", "y", "z", "Bx", "By", "Bz", "Bn", "region_id"};
  else
    table.columns = {"x", "y", "z", "Bx", "By", "Bz", "region_id"};
  const std::vector<SpherePoint> s = sphere ? sphere_samples(probe) : std::vector<SpherePoint>{};
  const std::vector<Eigen::Vector2d> uv =
      plane ? plane_probe_coordinates(probe) : std::vector<Eigen::Vector2d>{};
  table.rows.reserve(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const auto loc = locator.locate(pts[k]);
    if (!loc)
      throw std::runtime_error("probe '" + probe.name + "': point outside the mesh");
    const Eigen::Vector3d b = loc->b_map * B_at(loc->tet, loc->bary);
    const double region = field.problem().mesh->tet_part[loc->tet];
    const Eigen::Vector3d x = pts[k] / length_unit;
    if (plane) {
      const Eigen::Vector2d w = uv[k] / length_unit;
      table.rows.push_back(
          {w.x(), w.y(), x.x(), x.y(), x.z(), b.x(), b.y(), b.z(), b.dot(probe.plane.n), region});
      continue;
    }
    if (!sphere) {
      table.rows.push_back({x.x(), x.y(), x.z(), b.x(), b.y(), b.z(), region});
      continue;
    }
    table.rows.push_back({s[k].theta * rad_to_deg, s[k].phi * rad_to_deg, x.x(), x.y(), x.z(),
                          b.x(), b.y(), b.z(), b.dot(s[k].e_rho), b.dot(s[k].e_theta),
                          b.dot(s[k].e_phi), region});
  }
  return table;
}

} // namespace

ProbeTable sample_probe_3d(const Field3D& field, const PointLocator3D& locator,
                           const ProbeSpec& probe, double length_unit,
                           const RecoveredB3D* recovered) {
  return sample_probe(field, locator, probe, length_unit,
                      [&](std::size_t t, const std::array<double, 4>& bary) {
                        return recovered ? recovered->at(t, bary) : field.B(t, bary);
                      });
}

ProbeTable sample_probe_3d(const Field3D& field, const PointLocator3D& locator,
                           const ProbeSpec& probe, double length_unit,
                           const PatchRecovery3D& recovery) {
  return sample_probe(
      field, locator, probe, length_unit,
      [&](std::size_t t, const std::array<double, 4>& bary) { return recovery.B(t, bary); });
}

} // namespace magfem
