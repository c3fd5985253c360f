#pragma once
// Force and torque from analytic (or any) fields:
//  - Maxwell stress tensor on a sphere in air (thesis eqs. 3.41-3.44):
//      F = oint T.n dS,  T_ij = (1/mu0) (B_i B_j - delta_ij |B|^2 / 2),
//      torque about p = oint (x - p) x (T.n) dS.
//    Gauss-Legendre in theta, trapezoid (spectrally accurate for periodic data) in phi.
//  - Charge interaction: the force on magnets `on` in the field of magnets `by` is
//      F = mu0 [ oint sigma_on H_by dS + int rho_on H_by dV ],  torque = int (x - p) x dF.
//    For mu_r = 1 this equals the stress-tensor result on any surface separating the groups.
//    Adaptive: every face of `on` is split until the force and torque of each box agree with
//    those of its two halves to `tolerance` relative to the total.
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "validation/analytic_magnet.hpp"
#include "validation/charge_model.hpp"

namespace magfem {

struct ForceTorque {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // newton
  Eigen::Vector3d torque = Eigen::Vector3d::Zero(); // newton metre, about the given point
};

using FieldFunction = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;
// Evaluates B at many points at once (e.g. a threaded ChargeModel or an FE field).
using BatchFieldFunction =
    std::function<std::vector<Eigen::Vector3d>(const std::vector<Eigen::Vector3d>&)>;

// Force and torque on everything inside the sphere (centre, radius in metres) from B (tesla)
// on the sphere, which must lie in air. n_theta Gauss points in theta, n_phi in phi.
ForceTorque maxwell_stress_on_sphere(const FieldFunction& B, const Eigen::Vector3d& center,
                                     double radius, const Eigen::Vector3d& torque_point,
                                     int n_theta, int n_phi);
ForceTorque maxwell_stress_on_sphere(const BatchFieldFunction& B, const Eigen::Vector3d& center,
                                     double radius, const Eigen::Vector3d& torque_point,
                                     int n_theta, int n_phi);

struct ChargeInteractionOptions {
  double tolerance = 1e-6;  // relative to the sum of |contributions| of force and torque
  int gauss_order = 6;      // per direction per box on the `on` magnets
  int max_depth = 24;       // binary splits per face
  ChargeModelOptions field; // quadrature of the field of `by`
};

// Force and torque (about torque_point) on the magnets `on` exerted by the magnets `by`
// (mu_r = 1, no permeable boundaries). The two groups must not overlap.
ForceTorque charge_interaction(const std::vector<AnalyticMagnet>& on,
                               const std::vector<AnalyticMagnet>& by,
                               const Eigen::Vector3d& torque_point,
                               const ChargeInteractionOptions& options = {});

} // namespace magfem
