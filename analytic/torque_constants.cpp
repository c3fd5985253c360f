#include "analytic/torque_constants.hpp"

#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"
#include "core/gauss_legendre.hpp"

namespace magfem {

std::vector<CoilQuadraturePoint> torque_quadrature(const CoilField& coil, const CoilRule& rule) {
  const auto* c = std::get_if<SphericalCoil>(&coil.coil().shape);
  if (!c)
    return coil.volume_quadrature(rule.n_r, rule.n_azimuth);
  const Placement& place = coil.coil().placement;
  const double j = coil.coil().turns / coil.cross_section_area();
  const QuadratureRule gr = gauss_legendre(rule.n_r, c->r_inner, c->r_outer);
  std::vector<CoilQuadraturePoint> out;
  const double u0 = std::cos(c->alpha_max), u1 = std::cos(c->alpha_min);
  for (int p = 0; p < rule.n_alpha_panels; ++p) {
    const double a = u0 + (u1 - u0) * p / rule.n_alpha_panels;
    const double b = u0 + (u1 - u0) * (p + 1) / rule.n_alpha_panels;
    const QuadratureRule gu = gauss_legendre(rule.n_alpha, a, b);
    for (std::size_t i = 0; i < gr.x.size(); ++i)
      for (std::size_t k = 0; k < gu.x.size(); ++k) {
        const double r = gr.x[i], ct = gu.x[k];
        const double rho = r * std::sqrt(std::max(0.0, 1.0 - ct * ct));
        // r^2 dr dcos(alpha) dbeta, the azimuth by the trapezoidal (periodic) rule.
        const double w = gr.w[i] * gu.w[k] * r * r * 2.0 * pi / rule.n_azimuth;
        for (int m = 0; m < rule.n_azimuth; ++m) {
          const double beta = 2.0 * pi * (m + 0.5) / rule.n_azimuth;
          const Vec3 xl(rho * std::cos(beta), rho * std::sin(beta), r * ct);
          const Vec3 dir(-std::sin(beta), std::cos(beta), 0.0);
          out.push_back({place.to_global(xl), w, place.rotation * (j * dir)});
        }
      }
  }
  return out;
}

std::vector<TorqueConstants> torque_constants_rotating(const std::vector<CoilField>& coils,
                                                       const std::vector<Eigen::Matrix3d>& rotor,
                                                       const FieldAtPoints& b_rotor,
                                                       const CoilRule& rule) {
  std::vector<std::vector<CoilQuadraturePoint>> rules;
  std::size_t per_orientation = 0;
  for (const auto& c : coils) {
    rules.push_back(torque_quadrature(c, rule));
    per_orientation += rules.back().size();
  }
  std::vector<Eigen::Vector3d> points;
  points.reserve(per_orientation * rotor.size());
  for (const auto& r : rotor)
    for (const auto& rule : rules)
      for (const auto& q : rule)
        points.push_back(r.transpose() * q.x);
  const std::vector<Eigen::Vector3d> b = b_rotor(points);
  if (b.size() != points.size())
    throw std::logic_error("torque_constants_rotating: field returned the wrong number of values");
  std::vector<TorqueConstants> out;
  std::size_t i = 0;
  for (const auto& r : rotor) {
    TorqueConstants g = TorqueConstants::Zero(3, static_cast<Eigen::Index>(coils.size()));
    for (std::size_t k = 0; k < rules.size(); ++k)
      for (const auto& q : rules[k]) {
        const Eigen::Vector3d bg = r * b[i++];
        g.col(static_cast<Eigen::Index>(k)) += q.weight * q.x.cross(q.j_per_ampere.cross(bg));
      }
    out.push_back(g);
  }
  return out;
}

TorqueConstants torque_constants(const std::vector<CoilField>& coils, const FieldAtPoints& b,
                                 const CoilRule& rule) {
  return torque_constants_rotating(coils, {Eigen::Matrix3d::Identity()}, b, rule).front();
}

} // namespace magfem
