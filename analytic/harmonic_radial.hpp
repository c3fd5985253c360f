#pragma once
// Radial part of the scalar potential of a spherical shell magnet R_i <= rho <= R_o (mu_r = 1
// everywhere) whose magnetization does not depend on rho, per degree n.
//
// With M = sum Mr_nm Y_nm e_rho + Mp_nm rho grad Y_nm (+ toroidal), H = -grad psi and
// psi = sum psi_nm(rho) Y_nm, the magnetic charges are
//   volume   -div M = -c_nm Y_nm / rho,   c_nm = 2 Mr_nm - n(n+1) Mp_nm,
//   surface  +Mr_nm Y_nm at R_o,  -Mr_nm Y_nm at R_i,
// and the free-space Green's function 1/|x - x'| = sum 4 pi/(2n+1) r_<^n / r_>^(n+1) Y Y'
// gives, in all three regions at once,
//   psi_nm(rho) = [Mr (W - 2V) + n(n+1) Mp V] / (2n+1),
//   W(rho) = R_o^2 g(rho, R_o) - R_i^2 g(rho, R_i),  V(rho) = int_{R_i}^{R_o} rho' g(rho, rho')
//   drho', g(rho, rho') = r_<^n / r_>^(n+1).
// An infinitely permeable sphere at R_s > R_o (psi = 0 there: H tangential vanishes) adds the
// regular solution -psi_nm^out(R_s) (rho / R_s)^n for rho < R_s (the image of the exterior
// field). Every power is written as a ratio <= 1, e.g. R_o (R_o/rho)^(n+1) instead of
// R_o^(n+2) / rho^(n+1), so no degree overflows (terms that underflow are negligible).
#include <optional>
#include <vector>

namespace magfem {

// psi_nm(rho) = alpha Mr_nm + beta Mp_nm, and the rho-derivatives (metres, dimensionless).
struct RadialFactors {
  double alpha = 0, beta = 0;
  double d_alpha = 0, d_beta = 0;
};

class ShellRadialSolution {
public:
  // r_inner may be 0 (solid sphere); permeable_radius, if given, must exceed r_outer.
  ShellRadialSolution(double r_inner, double r_outer, std::optional<double> permeable_radius);

  // Factors for n = 0..n_max at radius rho > 0 (rho <= R_s when bounded).
  void evaluate(double rho, int n_max, std::vector<RadialFactors>& out) const;

private:
  void add_exterior(double rho, int n_max, std::vector<RadialFactors>& out) const;
  void add_interior(double rho, int n_max, std::vector<RadialFactors>& out) const;
  void add_in_magnet(double rho, int n_max, std::vector<RadialFactors>& out) const;
  void add_image(double rho, int n_max, std::vector<RadialFactors>& out) const;

  double r_inner_, r_outer_;
  std::optional<double> r_s_;
};

} // namespace magfem
