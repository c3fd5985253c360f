#pragma once
// A-posteriori error estimate of a 2D (A_z) or axisymmetric (A_phi) solution: Zienkiewicz-Zhu
// recovery of B, region by region.
//
// Why recovery and not residuals: the P1/P2 B_h is discontinuous across elements, and the
// exact B is smoother than B_h everywhere except across material interfaces, where only
// B_n and H_t are continuous. The superconvergent patch recovery of each region separately
// (PatchRecovery2D, never across an interface, where B_t jumps by mu_r; the same object the
// probes read) gives a B* that is closer to B than B_h is; B* - B_h then measures the error.
// Residual estimators need constants that depend on the element shape and on mu_r, which
// would have to be tuned per problem; the recovery needs none and its effectivity is tested
// against exact answers (tests/pipeline/test_error_estimate2d.cpp).
//
// Per element K:
//   eta_K^2 = integral_K (B* - B_h) . (H(B*) - H(B_h)) dV      (J/m planar, J axisymmetric)
// with H from the region's law (magnets: the remanence cancels in the difference; soft iron:
// monotone, so the product is >= 0). The open-boundary shell is a region of its own, recovered
// in its mapped coordinates, and its eta_K^2 carries the transformation's metric (nu0 d . T d
// with T the planar or the meridional curl metric, shell_transform.hpp), so the exterior's
// error is in the sum as the 3D estimate's is (error_estimate3d.hpp). For a linear problem
// solved by Galerkin,
//   |W - W_h| = (1/2) ||B - B_h||_E^2  exactly,
// so sum_K eta_K^2 / 2 estimates the error of the stored energy itself; the estimate is
// reported relative to the energy, and as the relative error in the energy norm.
#include <string>
#include <vector>

#include "postproc/patch_recovery2d.hpp"

namespace magfem {

struct ErrorEstimate2D {
  std::string indicator = "zz_recovery_per_region"; // summary.json error_estimate.indicator
  std::vector<double> eta2;         // per triangle: eta_K^2 (J/m planar, J axi), the shell's too
  double total_eta2 = 0;            // sum of eta2
  double energy_error_pct = 0;      // 100 * (total_eta2 / 2) / W: estimated relative error of W
  double energy_norm_error_pct = 0; // 100 * sqrt(total_eta2 / (2 W)): relative energy-norm error
  std::size_t degraded_patches = 0; // PatchRecovery2D::n_degraded
};

// recovery: of the solution's field, shell included; energy: the solution's stored energy W
// (J/m planar, J axisymmetric; energy2d.hpp).
ErrorEstimate2D estimate_error_2d(const PatchRecovery2D& recovery, double energy);

} // namespace magfem
