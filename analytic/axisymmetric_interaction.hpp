#pragma once
// Interaction of magnets that are each axisymmetric about their own axis through a common
// centre (the origin), in the harmonic form: a Legendre series in the angle between the axes.
//
// Covered: spherical segments with the full phi range (spheres, shells, hemispheres, polar
// caps and spherical rings theta_min..theta_max), centred on the origin and placed by a pure
// rotation, magnetized parallel to their own axis or radially from the origin, mu_r = 1, no
// permeable boundaries. One group ("inner") must lie within radius a and the other ("outer")
// beyond radius b > a (a sphere in air separates them), which the compensator satisfies.
// Not covered (the caller keeps the charge interaction): bodies off the centre, phi-limited
// segments, cylinders, boxes, touching or interleaved groups, imaging.
//
// Method. With H = -grad psi, the energy of the rigid inner magnets in the outer ones' field is
//   W = mu0 int M_A . grad psi_B dV.
// For r < b, psi_B = (1/4pi) sum_n Q_n r^n P_n(x.b/r) with the exterior moments
//   Q_n = int M_B . grad(r^-(n+1) P_n(cos t)) dV   (t from B's axis b),
// and the interior moments of A are q_n = int M_A . grad(r^n P_n(cos t)) dV (t from A's axis
// a). Both are charge moments (int rho f + oint sigma f, integrated by parts). The addition
// theorem (Funk-Hecke for an axisymmetric body) reduces the overlap to
//   W(gamma) = mu0/(4pi) sum_n q_n Q_n P_n(cos gamma),   cos gamma = a.b,
// so the torque on A about the centre is T_A = -dW/dc (a x b) with c = cos gamma, and the
// force on A (translate A: grad of a degree-n solid harmonic is one of degree n-1, evaluated
// at the unit vector a) is
//   F_A = -mu0/(4pi) sum_n Q_n q_{n-1} [n P_n(c) a + P_n'(c) (b - c a)].
// On the outer group: -T_A and -F_A (an isolated pair). With several bodies per group the
// pairs add. The moments are closed forms: r-integrals of powers and theta-integrals
// int P_k dx = (P_{k+1} - P_{k-1}) / (2k+1); each term is O(1), so a curve costs microseconds.
//
// Truncation: |q_n Q_n| <= C a^3 (a/b)^(n-1) times an algebraic factor from |P_k| <= 1 and
// |sin(gamma) P_n'(cos gamma)| <= sqrt(n(n+1)/2); n_max is the smallest degree whose tail
// bound (summed explicitly, then geometrically) is below tolerance times the angle-independent
// scale sum |term bound|. The bound is rigorous, not an estimate.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "analytic/analytic_magnet.hpp"

namespace magfem {

// One magnet in its own frame: axis (global unit vector), r_inner..r_outer (metres),
// theta_min..theta_max from the axis (radians), magnetization M (A/m, signed) along +axis
// (parallel) or along +e_r (radial from the centre).
struct AxisymmetricBody {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double r_inner = 0, r_outer = 0;
  double theta_min = 0, theta_max = 0;
  bool radial = false;
  double M = 0;
};

// The body a magnet describes, or nullopt with the reason in *why (e.g. "not centred").
std::optional<AxisymmetricBody> axisymmetric_body(const AnalyticMagnet& magnet,
                                                  std::string* why = nullptr);

// The moments that give a body's potential outside the sphere of radius a >= r_outer:
//   psi(x) = (1/4pi) sum_n q_n r^-(n+1) P_n(x.axis / r),  q_n = a^(n+2) value[n],
// q_n = int M . grad(r^n P_n(cos t)) dV (closed forms, see above); bound[n] >= |value[n]|.
struct AxisymmetricMoments {
  std::vector<double> value, bound; // n = 0..n_max
};
AxisymmetricMoments axisymmetric_source_moments(const AxisymmetricBody& body, double a, int n_max);

struct AxisymmetricInteractionOptions {
  double tolerance = 1e-10; // truncation bound relative to the series' scale (see above)
  int n_limit = 200000;     // refuse (std::domain_error) if more degrees would be needed
};

struct AxisymmetricInteraction {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // on the `on` group, N
  Eigen::Vector3d torque = Eigen::Vector3d::Zero(); // on the `on` group about the centre, N m
  double energy = 0;                                // J (zero at infinite separation)
  int n_max = 0;                                    // degrees summed
  double torque_bound = 0;                          // |truncation error| of |torque|, N m
  double force_bound = 0;                           // |truncation error| of |force|, N
};

// Force and torque on `on` exerted by `by`. Throws std::invalid_argument if a magnet is not
// covered or the groups are not separated by a sphere about the origin (the message says
// why), std::domain_error beyond n_limit.
AxisymmetricInteraction
axisymmetric_interaction(const std::vector<AnalyticMagnet>& on,
                         const std::vector<AnalyticMagnet>& by,
                         const AxisymmetricInteractionOptions& options = {});

} // namespace magfem
