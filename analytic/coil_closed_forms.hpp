#pragma once
// Exact references for coaxial coils of rectangular cross-section (thick solenoids), for the
// tests of the coil source field (sources/) and of the FE solver with coils. They share only
// Maxwell's loop mutual inductance (sources/loop_field.hpp, itself tested against Neumann's
// double line integral) with the code they check: the field and force paths of sources/ go
// through the loop *field* and the bundle quadratures instead. SI units; a coil's ampere-turns
// are spread uniformly over its cross-section; axis = z.
//
// Cross-checks (tests/sources/test_coil_closed_forms.cpp): the thick-coil self-inductance
// tends to the current sheet's as the winding thins; the current sheet's numerical integral
// equals Lorenz's closed form (Nagaoka's coefficient) to 1e-10 and reproduces Nagaoka's table;
// the Brooks coil gives Grover's 1.6994e-6 a N^2 H (a = mean radius in m); Wheeler's multilayer
// approximation agrees within its stated 1 %.

namespace magfem {

// A coil on the z axis: r_inner <= rho <= r_outer, z_min <= z <= z_max, `turns` turns.
// r_inner == r_outer is a current sheet (single-layer solenoid).
struct CoaxialCoil {
  double r_inner = 0, r_outer = 0;
  double z_min = 0, z_max = 0;
  double turns = 1;
};

// On-axis field H_z (A/m) at height z of `coil` carrying `current` per turn (closed form: the
// sheet fields (K/2)[u/sqrt(a^2 + u^2)] integrated over the radius give
// (J/2) [u ln((r_o + sqrt(r_o^2 + u^2)) / (r_i + sqrt(r_i^2 + u^2)))] between u = z - z_max and
// u = z - z_min, written with asinh for accuracy).
double coaxial_coil_axial_H(const CoaxialCoil& coil, double current, double z);

// Nagaoka's coefficient K_N of a current sheet of radius a and length l, from Lorenz's closed
// form K_N = 4 / (3 pi k') [(k'^2 / k^2)(K(k) - E(k)) + E(k) - k], k^2 = 4a^2 / (4a^2 + l^2), so
// that L = mu0 pi a^2 N^2 K_N / l.
double nagaoka_coefficient(double radius, double length);
double current_sheet_self_inductance(double radius, double length, double turns);

// Self-inductance (H) by the quadruple integral of Maxwell's formula over the cross-section,
// L = (N / A)^2 int int M(a1, a2, z2 - z1) dA1 dA2, reduced to three dimensions (the z
// difference d with weight (l - |d|)) and to the half a1 < a2; the logarithmic singularity at
// a1 = a2, d = 0 is integrated in Duffy coordinates with panels graded towards it. `order` is
// the Gauss points per panel and direction; the default agrees with order 32 to 1e-13.
double coaxial_coil_self_inductance(const CoaxialCoil& coil, int order = 16);

// Mutual inductance (H) between two coaxial coils whose cross-sections do not overlap, and the
// axial force (N) on `b` from `a` (F_z = I_a I_b dM/dz_b; negative = b pulled towards -z).
// Composite Gauss in the radii and in the z difference (split where its weight has kinks),
// refined until two levels agree to 1e-11; throws std::invalid_argument for overlapping
// cross-sections.
double coaxial_mutual_inductance(const CoaxialCoil& a, const CoaxialCoil& b);
double coaxial_axial_force(const CoaxialCoil& a, const CoaxialCoil& b, double current_a,
                           double current_b);

} // namespace magfem
