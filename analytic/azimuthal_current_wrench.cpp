#include "analytic/azimuthal_current_wrench.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>

#include "core/constants.hpp"
#include "core/gauss_legendre.hpp"

namespace magfem {

namespace {

// Two unit vectors completing `axis` to a right-handed frame.
void frame(const Eigen::Vector3d& axis, Eigen::Vector3d& e1, Eigen::Vector3d& e2) {
  const Eigen::Vector3d t =
      std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  e1 = (t - t.dot(axis) * axis).normalized();
  e2 = axis.cross(e1);
}

// Panels on [lo, hi] halving towards both ends down to `finest`.
void graded_panels(double lo, double hi, double finest, int n, std::vector<double>& x,
                   std::vector<double>& w) {
  auto add = [&](double a, double b) {
    const QuadratureRule g = gauss_legendre(n, a, b);
    x.insert(x.end(), g.x.begin(), g.x.end());
    w.insert(w.end(), g.w.begin(), g.w.end());
  };
  // Distances from each end: 0, then half / 2^k from the smallest above `finest` up to half.
  const double half = 0.5 * (hi - lo);
  std::vector<double> d{half};
  for (double h = 0.5 * half; h > finest; h *= 0.5) {
    d.push_back(h);
  }
  d.push_back(0.0);
  for (std::size_t k = 0; k + 1 < d.size(); ++k) {
    add(lo + d[k + 1], lo + d[k]);
    add(hi - d[k], hi - d[k + 1]);
  }
}

} // namespace

Eigen::Vector3d placed_coil_B(const PlacedCoil& placed, const CoaxialCoilField& field,
                              const Eigen::Vector3d& x) {
  const Eigen::Vector3d d = x - placed.origin;
  const double z = d.dot(placed.axis);
  const Eigen::Vector3d radial = d - z * placed.axis;
  const double rho = radial.norm();
  const MeridianField h = field.H(rho, z);
  Eigen::Vector3d b = mu0 * h.h_z * placed.axis;
  if (rho > 0) {
    b += mu0 * h.h_rho * radial / rho;
  }
  return b;
}

Wrench azimuthal_current_wrench(const PlacedCoil& target, double current,
                                const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& B,
                                const Eigen::Vector3d& pivot, const WrenchQuadrature& q) {
  const CoaxialCoil& c = target.coil;
  if (!(c.z_max > c.z_min && c.r_outer >= c.r_inner && c.r_inner >= 0 && q.n_phi >= 4)) {
    throw std::invalid_argument("azimuthal_current_wrench: bad coil or quadrature");
  }
  const Eigen::Vector3d axis = target.axis.normalized();
  Eigen::Vector3d e1, e2;
  frame(axis, e1, e2);
  std::vector<double> zx, zw, rx, rw;
  graded_panels(c.z_min, c.z_max, q.finest, q.gauss, zx, zw);
  const double length = c.z_max - c.z_min;
  // Current per unit length along the axis and per unit radius (or the sheet's per length).
  double density;
  if (c.r_outer == c.r_inner) {
    rx = {c.r_inner};
    rw = {1.0};
    density = c.turns * current / length;
  } else {
    for (int p = 0; p < q.rho_panels; ++p) {
      const double h = (c.r_outer - c.r_inner) / q.rho_panels;
      const QuadratureRule g = gauss_legendre(q.gauss, c.r_inner + p * h, c.r_inner + (p + 1) * h);
      rx.insert(rx.end(), g.x.begin(), g.x.end());
      rw.insert(rw.end(), g.w.begin(), g.w.end());
    }
    density = c.turns * current / (length * (c.r_outer - c.r_inner));
  }
  Wrench out;
  const double dphi = 2 * pi / q.n_phi;
  for (int k = 0; k < q.n_phi; ++k) {
    const double phi = (k + 0.5) * dphi;
    const Eigen::Vector3d radial = std::cos(phi) * e1 + std::sin(phi) * e2;
    const Eigen::Vector3d tangent = axis.cross(radial);
    for (std::size_t i = 0; i < rx.size(); ++i) {
      for (std::size_t j = 0; j < zx.size(); ++j) {
        const Eigen::Vector3d x = target.origin + zx[j] * axis + rx[i] * radial;
        // current element: density * rho dphi dz (drho) along the tangent
        const double w = density * rw[i] * zw[j] * rx[i] * dphi;
        const Eigen::Vector3d f = w * tangent.cross(B(x));
        out.force += f;
        out.torque += (x - pivot).cross(f);
      }
    }
  }
  return out;
}

} // namespace magfem
