#pragma once
// Force and torque from analytic fields:
//  - Maxwell stress tensor on a sphere in air: maxwell_stress_on_sphere and ForceTorque live
//    in postproc/maxwell_stress.hpp (pure quadrature on a field callback, shared with the FE
//    postprocessing); included here so that callers of this header see them.
//  - Charge interaction: the force on magnets `on` in the field of magnets `by` is
//      F = mu0 [ oint sigma_on H_by dS + int rho_on H_by dV ],  torque = int (x - p) x dF.
//    For mu_r = 1 this equals the stress-tensor result on any surface separating the groups.
//    Adaptive: every face of `on` is split until the force and torque of each box agree with
//    those of its two halves to `tolerance` relative to the total.
#include <vector>

#include <Eigen/Core>

#include "postproc/maxwell_stress.hpp"
#include "analytic/analytic_magnet.hpp"
#include "analytic/charge_model.hpp"

namespace magfem {

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
