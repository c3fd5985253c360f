#pragma once
// Open boundary by a shell transformation (the idea of GetDP's VolSphShell/VolCylShell): the
// shell R1 <= r < R2 of the mesh stands for the whole exterior R1 <= r' < infinity through
// the radial map r' = f(r) = R1 (R2 - R1) / (R2 - r). For the Laplace operator in the
// exterior this is exact; the weak form in the shell carries the metric tensor
//   T = |det J| J^-1 J^-T,  J = dx'/dx = (f/r) P_t + f' P_r,
// with P_r = r_hat r_hat^T and P_t = I - P_r. A multipole of order n decays like
// (R1/r')^n (2D) or (R1/r')^(n+1) (3D), which becomes the polynomial ((R2-r)/(R2-R1))^n or
// ^(n+1) in the shell: dipoles are reproduced exactly by order-2 elements, so the truncation
// error of the open boundary is negligible. The outer sphere r = R2 is infinity (potential 0).
#include <Eigen/Core>

namespace magfem {

struct ShellTransform {
  double r_inner = 0; // R1
  double r_outer = 0; // R2

  // Metric tensor T at point x in the shell (dimension 2 or 3).
  template <int Dim>
  Eigen::Matrix<double, Dim, Dim> metric(const Eigen::Matrix<double, Dim, 1>& x) const {
    const double r = x.norm();
    const double gap = r_outer - r; // > 0 at quadrature points
    const Eigen::Matrix<double, Dim, 1> e = x / r;
    const Eigen::Matrix<double, Dim, Dim> pr = e * e.transpose();
    const Eigen::Matrix<double, Dim, Dim> pt = Eigen::Matrix<double, Dim, Dim>::Identity() - pr;
    const double f = r_inner * (r_outer - r_inner) / gap;
    const double df = f / gap;
    if constexpr (Dim == 2) {
      // |det J| = (f/r) f'
      return (df * r / f) * pt + (f / (r * df)) * pr;
    } else {
      // |det J| = (f/r)^2 f'
      return df * pt + (f * f / (r * r * df)) * pr;
    }
  }

  // The axisymmetric shell is the 3D spherical map seen in the meridional (r-z) plane, and the
  // unknown is a vector potential: B pulls back as a 2-form, B_mesh = det J J^-1 B', so
  //   integral nu |B'|^2 dV' = integral nu B_mesh . (J^T J / |det J|) B_mesh dV,
  //   J^T J / |det J| = P_t / f' + f' (r/f)^2 P_r      (x: a meridional point).
  Eigen::Matrix2d curl_metric_meridional(const Eigen::Vector2d& x) const {
    const double r = x.norm();
    const double gap = r_outer - r;
    const Eigen::Vector2d e = x / r;
    const Eigen::Matrix2d pr = e * e.transpose();
    const double f = r_inner * (r_outer - r_inner) / gap;
    const double df = f / gap;
    return (1 / df) * (Eigen::Matrix2d::Identity() - pr) + (df * (r / f) * (r / f)) * pr;
  }

  // The physical point x' = (f(r)/r) x that the shell point x stands for.
  Eigen::Vector3d map(const Eigen::Vector3d& x) const {
    const double r = x.norm();
    return (r_inner * (r_outer - r_inner) / ((r_outer - r) * r)) * x;
  }
  // |det J| J^-1 (J is symmetric): a physical vector field v' enters the shell's weak form as
  // integral v'(x') . J^-T grad N |det J| dx = integral (|det J| J^-1 v') . grad N dx.
  Eigen::Matrix3d det_times_inverse_jacobian(const Eigen::Vector3d& x) const {
    const Radial q = radial(x);
    return (q.f / q.r) * q.df * q.pt + (q.f / q.r) * (q.f / q.r) * q.pr;
  }
  // J^-1 (maps -grad phi in the mesh to the physical -grad' phi).
  Eigen::Matrix3d inverse_jacobian(const Eigen::Vector3d& x) const {
    const Radial q = radial(x);
    return (q.r / q.f) * q.pt + (1 / q.df) * q.pr;
  }
  // |det J| = (f/r)^2 f'.
  double det_jacobian(const Eigen::Vector3d& x) const {
    const Radial q = radial(x);
    return (q.f / q.r) * (q.f / q.r) * q.df;
  }

private:
  // r, f(r), f'(r) and the radial/tangential projectors at a 3D shell point.
  struct Radial {
    double r, f, df;
    Eigen::Matrix3d pr, pt;
  };
  Radial radial(const Eigen::Vector3d& x) const {
    Radial q;
    q.r = x.norm();
    const double gap = r_outer - q.r;
    const Eigen::Vector3d e = x / q.r;
    q.pr = e * e.transpose();
    q.pt = Eigen::Matrix3d::Identity() - q.pr;
    q.f = r_inner * (r_outer - r_inner) / gap;
    q.df = q.f / gap;
    return q;
  }
};

} // namespace magfem
