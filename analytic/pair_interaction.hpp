#pragma once
// Charge interaction by face-pair cubature: the force on magnets A exerted by magnets B,
//   F_A = mu0/(4 pi) int_A int_B q_A q_B (x_A - x_B) / |x_A - x_B|^3,
// q = sigma dS on faces and rho_m dV in volumes (radial magnetization), torque about p
// int (x_A - p) x dF. This is the double integral that charge_interaction
// (analytic/analytic_force.hpp) evaluates as "quadrature of A in the field of B", but
// organised as a dual tree: a pair of parameter boxes (one of A, one of B) is integrated with
// a tensor Gauss rule of n_A points per direction on A and n_B on B, each chosen from that
// side's distance/size ratio,
//   rho_A = (|c_A - c_B| - r_B) / r_A,   n_A = ceil( ln(1/tol) / (2 ln(rho_A + sqrt(rho_A^2-1))) )
// (the Bernstein-ellipse rate of Gauss rules for a kernel whose singularity lies rho_A box
// radii away), and split (the side that needs the higher order) while either order would
// exceed max_order. A far pair of a 2 mm cap and a 10 mm sphere patch costs 4 x 36 kernel
// evaluations instead of the 36-point rule of every half box and the full source tree per
// point of the field approach. Faces that touch across the groups are split to a minimum box
// size and then taken at max_order: the 1/r^2 kernel is integrable over the 4D pair, so the
// unresolved remainder shrinks with the box area.
//
// Two refinements (issue 14, segment arrays 7x -> 24x faster than the field quadrature):
// surface pairs also take orders from where the kernel's singularity lies in the complex
// parameter plane, which across a narrow gap between parallel faces allows boxes about as
// large as the gap (surface_patch_order.hpp); and where a plane through the torque point
// mirrors both groups onto themselves, one magnet pair of each mirrored two is integrated
// and the other added as its mirror image (mirror_symmetry.hpp).
//
// Accuracy printed: the difference from the same computation at 100 x the tolerance. The
// orders converge geometrically, so it bounds the coarser result's error and overstates the
// returned one's (tested against exact and converged references); it costs ~50 % more.

// Action = reaction: the pair sum is antisymmetric in A and B term by term, so the force on
// B is minus the force on A and the torques about one point are opposite (to round-off). With
// a mirror symmetry, swapping the groups may integrate the other pair of a mirrored two; then
// this holds to the quadrature's accuracy (mirrored boxes can round to different orders).
#include <vector>

#include <Eigen/Core>

#include "postproc/maxwell_stress.hpp"
#include "analytic/analytic_magnet.hpp"

namespace magfem {

struct PairInteractionOptions {
  double tolerance = 1e-6; // relative quadrature error per box pair (a priori)
  int max_order = 8;       // Gauss points per direction per box, at most
  int n_threads = 0;       // 0 = std::thread::hardware_concurrency()
  // Orders of surface box pairs also from the singularity's complex offset (lower across
  // narrow gaps between parallel faces, surface_patch_order.hpp); false = bounding spheres
  // only (the earlier, slower rule: an independent reference).
  bool patch_orders = true;
  // Integrate one magnet pair of each two mirrored onto each other by a plane through the
  // torque point (analytic/mirror_symmetry.hpp); false = every pair.
  bool mirror_symmetry = true;
};

struct PairInteraction {
  ForceTorque on_A;        // force on A, torque on A about the torque point
  double force_error = 0;  // estimated |error of the force|, N
  double torque_error = 0; // estimated |error of the torque|, N m
  long box_pairs = 0;      // box pairs integrated
  long kernel_evals = 0;   // point pairs
  bool mirrored = false;   // a mirror symmetry halved the magnet pairs integrated
};

// Force and torque (about torque_point) on the magnets `on` exerted by the magnets `by`
// (mu_r = 1, no permeable boundaries). The groups must not overlap. Throws
// std::invalid_argument for invalid shapes (check_shape).
PairInteraction pair_interaction(const std::vector<AnalyticMagnet>& on,
                                 const std::vector<AnalyticMagnet>& by,
                                 const Eigen::Vector3d& torque_point,
                                 const PairInteractionOptions& options = {});

} // namespace magfem
