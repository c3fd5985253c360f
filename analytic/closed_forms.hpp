#pragma once
// Exact fields that need no discretization: references for the harmonic and charge models
// and for the FE solver. All inputs and outputs SI (metres, tesla, amperes); mu_r = 1.
#include <Eigen/Core>

namespace magfem {

// --- Uniformly magnetized sphere and shell ---------------------------------------------
// `remanence` is B_r times the unit magnetization direction (tesla), i.e. mu0 M.
// Inside: B = (2/3) mu0 M. Outside: the field of the dipole m = (4 pi / 3) a^3 M.
Eigen::Vector3d uniform_sphere_B(const Eigen::Vector3d& x, const Eigen::Vector3d& center,
                                 double radius, const Eigen::Vector3d& remanence);
// A shell r_inner <= |x - center| <= r_outer with uniform M is the sphere of r_outer minus the
// sphere of r_inner with the same M: B = 0 in the cavity, (2/3) mu0 M plus the field of the
// dipole -(4 pi / 3) r_inner^3 M in the shell, the dipole (4 pi / 3)(r_outer^3 - r_inner^3) M
// outside.
Eigen::Vector3d uniform_shell_B(const Eigen::Vector3d& x, const Eigen::Vector3d& center,
                                double r_inner, double r_outer, const Eigen::Vector3d& remanence);

// --- Uniformly magnetized infinite cylinder (2D, axis along z) ---------------------------
// `remanence` = mu0 M in the xy-plane. Inside B = mu0 M / 2; outside, with phi measured from
// M: B_r = (B_r / 2)(a/r)^2 cos(phi), B_phi = (B_r / 2)(a/r)^2 sin(phi) (the field of a 2D
// dipole). Its equivalent surface current K = M x n varies as the sine of the angle from M,
// i.e. the cosine of the angle from the pole lines' normal.
Eigen::Vector2d uniform_cylinder_B(const Eigen::Vector2d& x, const Eigen::Vector2d& center,
                                   double radius, const Eigen::Vector2d& remanence);

// --- Harwin's surface-current model of a diametric cylinder ------------------------------
// (000_4b10982579af20cb.txt, sec. 2.1.) Line currents I dtheta (I in A per radian of the
// circumference) sit on the magnet surface of radius `magnet_radius` and flow along -z on
// the half x > 0, along +z on the half x < 0, reversing at the pole lines (the y axis,
// phi = +-pi/2). With the current-free bands of eq. 4, no current flows within `band_half_width`
// (Delta) of either pole line. phi is measured from +x; the north pole line is +y.
struct HarwinCylinder {
  double current_per_rad = 0; // I, A/rad
  double magnet_radius = 0;   // r, metres
  double band_half_width = 0; // Delta, radians (eq. 4 only)
};

// Eq. 3: B_r(R, phi) = mu0 I / (2 pi R) ln[(R^2 + r^2 + 2 R r sin phi) / (R^2 + r^2 - 2 R r sin
// phi)] at distance R from the axis (valid inside and outside the current sheet, R != r on the pole
// lines, where it diverges logarithmically). Its Fourier series is (2 mu0 I / (pi R)) sum_{k odd}
// (-1)^{(k-1)/2} (r/R)^k sin(k phi) / k (R > r): the square wave of the current shows up as odd
// harmonics 1/3, 1/5, ... of the fundamental.
double harwin_eq3_radial_B(const HarwinCylinder& c, double R, double phi);

// Eq. 4 as derived here from the same line currents with the bands removed:
// B_r = mu0 I / (4 pi R) { ln[(S + 2 R r sin(phi - D)) / (S - 2 R r sin(phi + D))]
//                        + ln[(S + 2 R r sin(phi + D)) / (S - 2 R r sin(phi - D))] },
// S = R^2 + r^2, D = Delta. It reduces to eq. 3 for Delta = 0 and stays finite at the
// surface on the pole lines when Delta > 0.
double harwin_eq4_radial_B(const HarwinCylinder& c, double R, double phi);

// Eq. 4 exactly as printed in the paper: B_r 2 pi R / (mu I) = the two logarithms with
// numerator and denominator swapped. It equals -2 times harwin_eq4_radial_B (opposite sign
// and twice the prefactor of eq. 3), so the paper's fitted I for eq. 4 (3.6e4 A/rad, Fig. 4)
// belongs to this printed form; use it only to reproduce that figure.
double harwin_eq4_as_printed_radial_B(const HarwinCylinder& c, double R, double phi);

} // namespace magfem
