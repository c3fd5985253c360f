#pragma once
// A posteriori error estimate of a 3D scalar-potential solution (P1 or P2): the
// Zienkiewicz-Zhu indicator per element, in the energy norm,
//
//   eta_K^2 = int_K (B(H*) - B(H_h)) . (H* - H_h) dV          (J)
//
// with H* the superconvergent patch recovery (patch_recovery3d.hpp) and B(.) the region's
// law: mu |H* - H_h|^2 in linear media and magnets (the remanence cancels in the
// difference), the monotone B-H curve's own measure in nonlinear iron. For a linear problem
// this is the squared energy norm of H - H_h with H* in place of H, and the relative error
//
//   energy_norm_error_pct = 100 sqrt(sum eta_K^2 / (2 W_h + sum eta_K^2))
//
// The stored energy itself is off by half the squared error norm (the same keys as the 2D
// estimate, error_estimate2d.hpp), so its estimated relative error is
//
//   energy_error_pct = 100 (sum eta_K^2 / 2) / W_h.
//
// uses Galerkin orthogonality, ||H||^2 = ||H_h||^2 + ||H - H_h||^2 with ||H_h||^2 = 2 W_h
// (energy3d.hpp: W measured from the remanent state is (1/2) int mu |H|^2).
//
// The open-boundary shell stands for the whole exterior and can hold much of the error (on
// the magnetized sphere of tests/pipeline/test_adapt3d.cpp a 4x finer shell alone halves the
// true energy error). Its indicator is the same ZZ measure in the mapped coordinates: with
// d = G* - G_h the mesh-gradient difference recovered there (patch_recovery3d.hpp),
//
//   eta_K^2 = int_K mu0 d . T d dV,   T = |det J| J^-1 J^-T   (shell_transform.hpp),
//
// which is the physical int mu0 |J^-1 d|^2 dV' over the part of the exterior K stands for.
// With coils, H* - H_h holds only the potential's part (the coils' field is exact), and
// 2 W_h uses the total field.
#include <string>
#include <vector>

#include "postproc/patch_recovery3d.hpp"

namespace magfem {

struct ErrorEstimate3D {
  std::string indicator;            // how eta_K was computed, for summary.json
  std::vector<double> eta2_J;       // per tet: eta_K^2 (J), the shell's included
  double error_norm2_J = 0;         // sum of eta_K^2 (J)
  double energy_norm2_J = 0;        // 2 W_h (J)
  double energy_norm_error_pct = 0; // relative error of the field in the energy norm (above)
  double energy_error_pct = 0;      // relative error of the stored energy W (above)
  std::size_t degraded_patches = 0; // PatchRecovery3D::n_degraded
};

// energy_J: the solution's total energy W_h (EnergySummary3D::total_J), shell included.
ErrorEstimate3D estimate_error_3d(const PatchRecovery3D& recovery, double energy_J,
                                  int threads = 0);

// Relative energy-norm error in % from the two sums (see above); 0 when both vanish.
double energy_norm_error_pct(double error_norm2_J, double energy_norm2_J);

} // namespace magfem
