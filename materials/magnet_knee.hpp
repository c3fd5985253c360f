#pragma once
// The irreversible-demagnetization data of a magnet grade: its intrinsic coercivity H_cJ and
// the reversible temperature coefficients of B_r (alpha) and H_cJ (beta), all at the reference
// temperature 20 C, the temperature datasheets and IEC 60404-8-1 quote them at.
//
// Linear model: B_r(T) = B_r(20) (1 + alpha/100 (T - 20)), likewise H_cJ with beta. Datasheets
// give alpha and beta as the mean slope over 20..100 C (or 20..150 C); outside that range the
// model is an extrapolation.
//
// The knee: along the linear recoil line B = B_r(T) + mu0 mu_r H (H along the magnetization),
// the intrinsic curve J = B - mu0 H collapses near H = -H_cJ(T). A point of the magnet whose
// B . m_hat falls below knee_T = B_r(T) - mu0 mu_r H_cJ(T) is past the knee: it loses part of
// its remanence for good. (Rectangular-loop model: sintered NdFeB at 20 C; for grades with a
// rounded knee, such as ferrite, it is optimistic.)
#include <optional>

namespace magfem {

struct MagnetKnee {
  std::optional<double> HcJ_Apm;         // intrinsic coercivity at 20 C in A/m; none = unknown
  std::optional<double> alpha_pct_per_K; // d B_r / dT relative to B_r(20), %/K
  std::optional<double> beta_pct_per_K;  // d H_cJ / dT relative to H_cJ(20), %/K

  static constexpr double reference_C = 20.0;

  // B_r (or any 20 C quantity) at T with coefficient c (%/K); T = 20 returns it unchanged.
  static double at_temperature(double value_20, double coefficient_pct_per_K, double T_C) {
    return value_20 * (1.0 + coefficient_pct_per_K / 100.0 * (T_C - reference_C));
  }
};

// knee_T = B_r - mu0 mu_r H_cJ in T, for B_r and H_cJ at the same temperature.
double knee_flux_density(double B_r, double mu_r, double HcJ_Apm);

} // namespace magfem
