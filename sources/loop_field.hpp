#pragma once
// The circular filament loop, the kernel of every axisymmetric coil: its exact field by
// complete elliptic integrals, and Maxwell's mutual inductance of two coaxial loops with its
// derivative (the axial force). SI units; the loop's axis is the local z axis and positive
// current circulates counter-clockwise seen from +z.

namespace magfem {

// Complete elliptic integrals K(m) and E(m) of parameter m = k^2, from the arithmetic-geometric
// mean. The complementary modulus kc = sqrt(1 - m) is passed as well, computed by the caller
// from its own geometry, so that near m = 1 (a field point next to the filament) no precision is
// lost forming 1 - m. Requires 0 <= m < 1, kc > 0.
struct CompleteElliptic {
  double K, E;
};
CompleteElliptic complete_elliptic(double m, double kc);

// Field (A/m) in the meridian plane at cylindrical (rho, z) of a loop of radius a in the plane
// z = z0 carrying `current` (A). On the axis (rho = 0) h_rho = 0 and h_z is the textbook
// I a^2 / (2 (a^2 + dz^2)^{3/2}); the evaluation is free of cancellation near the axis and far
// from the loop. On the filament itself the field is infinite; zero is returned there (a
// quadrature node can only land on it by accident, and must not poison a sum).
struct MeridianField {
  double h_rho = 0, h_z = 0;
};
MeridianField loop_field(double a, double z0, double current, double rho, double z);

// Maxwell's mutual inductance (H) of two coaxial loops of radii a1, a2 whose planes are a
// distance d apart: M = mu0 sqrt(a1 a2) [(2/k - k) K(k) - (2/k) E(k)],
// k^2 = 4 a1 a2 / ((a1 + a2)^2 + d^2). Infinite (returned as +inf) for coincident loops.
double loop_mutual_inductance(double a1, double a2, double d);

// dM/dd, exact. The axial force on loop 2 (at z2 = z1 + d) from loop 1 is
// F_z = I1 I2 dM/dd (attractive for like currents: dM/dd < 0 for d > 0).
double loop_mutual_inductance_dd(double a1, double a2, double d);

} // namespace magfem
