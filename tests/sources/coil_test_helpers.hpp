#pragma once
// Shared references for the coil-field tests: brute-force volume Biot-Savart, line integrals of
// H along circles (Ampere's law), finite-difference divergence and curl.
#include <cmath>
#include <functional>
#include <vector>

#include "core/constants.hpp"
#include "core/gauss_legendre.hpp"
#include "mesh/placement3d.hpp"

namespace magfem::test {

using Field = std::function<Vec3(const Vec3&)>;

// Composite Gauss-Legendre on [a, b]: `panels` panels of `n` points.
inline QuadratureRule composite(double a, double b, int panels, int n) {
  QuadratureRule r;
  for (int p = 0; p < panels; ++p) {
    const QuadratureRule g =
        gauss_legendre(n, a + (b - a) * p / panels, a + (b - a) * (p + 1) / panels);
    r.x.insert(r.x.end(), g.x.begin(), g.x.end());
    r.w.insert(r.w.end(), g.w.begin(), g.w.end());
  }
  return r;
}

// Biot-Savart volume integral over an axisymmetric conductor (local frame, axis z) given by a
// map from parameters (u, v) to the meridian point (rho, z) with area element `jac`, carrying
// current density `j` (A/m^2) along phi: Gauss in (u, v), trapezoid in phi (periodic).
// Converges for field points a fraction of the bundle size away from it.
inline Vec3
brute_force_axisymmetric(const std::function<void(double, double, double&, double&, double&)>& map,
                         double u0, double u1, double v0, double v1, double j, const Vec3& x,
                         int panels, int n, int n_phi) {
  const QuadratureRule gu = composite(u0, u1, panels, n), gv = composite(v0, v1, panels, n);
  Vec3 h = Vec3::Zero();
  for (std::size_t a = 0; a < gu.x.size(); ++a) {
    for (std::size_t b = 0; b < gv.x.size(); ++b) {
      double rho, z, jac;
      map(gu.x[a], gv.x[b], rho, z, jac);
      const double w = gu.w[a] * gv.w[b] * jac * rho * (2 * pi / n_phi) * j;
      for (int k = 0; k < n_phi; ++k) {
        const double phi = 2 * pi * (k + 0.5) / n_phi;
        const Vec3 y(rho * std::cos(phi), rho * std::sin(phi), z);
        const Vec3 dir(-std::sin(phi), std::cos(phi), 0);
        const Vec3 r = x - y;
        h += w * dir.cross(r) / (4 * pi * std::pow(r.norm(), 3));
      }
    }
  }
  return h;
}

// Line integral of H around the ellipse centre + r1 cos t e1 + r2 sin t e2, oriented by
// e1 -> e2 (right-handed about e1 x e2), trapezoid rule with n points (spectral for smooth H).
inline double circulation(const Field& H, const Vec3& centre, const Vec3& e1, const Vec3& e2,
                          double r1, double r2, int n) {
  double s = 0;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * pi * k / n;
    const Vec3 x = centre + r1 * std::cos(t) * e1 + r2 * std::sin(t) * e2;
    const Vec3 dl = -r1 * std::sin(t) * e1 + r2 * std::cos(t) * e2;
    s += H(x).dot(dl) * (2 * pi / n);
  }
  return s;
}
inline double circulation(const Field& H, const Vec3& centre, const Vec3& e1, const Vec3& e2,
                          double radius, int n) {
  return circulation(H, centre, e1, e2, radius, radius, n);
}

// Jacobian dH_i/dx_j by fourth-order central differences with step h.
inline Mat3 jacobian(const Field& H, const Vec3& x, double h) {
  Mat3 jac;
  for (int j = 0; j < 3; ++j) {
    Vec3 e = Vec3::Zero();
    e[j] = h;
    jac.col(j) = (H(x - 2 * e) - 8 * H(x - e) + 8 * H(x + e) - H(x + 2 * e)) / (12 * h);
  }
  return jac;
}

inline Vec3 curl(const Mat3& jac) {
  return {jac(2, 1) - jac(1, 2), jac(0, 2) - jac(2, 0), jac(1, 0) - jac(0, 1)};
}

// Field of a point dipole m (A m^2) at the origin: H = (3 (m.e) e - m) / (4 pi r^3).
inline Vec3 dipole_H(const Vec3& m, const Vec3& x) {
  const double r = x.norm();
  const Vec3 e = x / r;
  return (3 * m.dot(e) * e - m) / (4 * pi * r * r * r);
}

} // namespace magfem::test
