#pragma once
// A magnetic material as a constitutive law, independent of the element type.
//
// Magnets are linear with remanence: B = mu0 mu_r H + B_r m_hat. The remanence is a *source*
// (the solver adds it per element, because its direction depends on the region's
// magnetization pattern); the law below only describes the reversible part, so for a magnet
// reluctivity() returns 1/(mu0 mu_r) and permeability() mu0 mu_r.
//
// Isotropic laws only: H = nu(|B|^2) B (B-formulations, 2D A_z) and B = mu(|H|^2) H
// (H-formulations, 3D scalar potential). Newton tangents follow from the derivative with
// respect to the squared magnitude: dH/dB = nu I + 2 nu' B B^T.
#include <memory>
#include <optional>
#include <string>

#include "materials/bh_curve.hpp"
#include "materials/magnet_knee.hpp"

namespace magfem {

enum class MaterialKind { linear, magnet, soft };

struct Material {
  std::string name;
  MaterialKind kind = MaterialKind::linear;
  double mu_r = 1.0; // relative permeability (recoil permeability for magnets; for soft
                     // materials the initial one, dB/dH(0) / mu0, for information only)
  double B_r = 0.0;  // remanence in T (magnets only)
  std::shared_ptr<const BhCurve> curve; // soft materials only
  MagnetKnee knee;                      // magnets: H_cJ and temperature coefficients (20 C)
  double temperature_C = MagnetKnee::reference_C; // magnets: B_r above holds at this temperature
  std::string source;                             // where the data comes from (for reports)

  bool is_nonlinear() const { return kind == MaterialKind::soft; }
  bool is_magnet() const { return kind == MaterialKind::magnet; }

  // nu(b2) in m/H and d nu / d(b2), b2 = |B|^2 in T^2.
  void reluctivity(double b2, double& nu, double& dnu_db2) const;
  // mu(h2) in H/m and d mu / d(h2), h2 = |H|^2 in (A/m)^2.
  void permeability(double h2, double& mu, double& dmu_dh2) const;

  // Permeability in H/m of the linear problem that gives the 3D Newton its starting point:
  // mu0 mu_r, or for soft materials the B-H curve's peak secant permeability. Why the peak:
  // with the iron at its most permeable, the linear solution's |H| in iron is below the
  // nonlinear one's nearly everywhere, and above the peak-permeability point the curve is
  // concave, where Newton started below the root approaches it without overshooting (started
  // above it, in saturation, its tangent is about mu0 and the first step overshoots by about
  // mu_r). Measured on TEAM 20 at 3000 AT (order 1, mesh scale 4): from the peak 8 Newton
  // iterations, from the initial slope 11, from a quarter of the peak 12.
  double start_permeability() const;

  // Magnets: this grade (at 20 C) at temperature T, B_r scaled by knee.alpha_pct_per_K.
  // Off 20 C the caller checks that knee.alpha_pct_per_K is known (logic_error otherwise).
  Material at_temperature(double T_C) const;
  // Magnets: H_cJ at temperature_C in A/m, and the knee B_r - mu0 mu_r H_cJ there in T; none
  // when H_cJ is unknown, or (off 20 C) its temperature coefficient beta is.
  std::optional<double> coercivity_Apm() const;
  std::optional<double> knee_T() const;

  // Constructors that fill the fields consistently for each kind.
  static Material make_linear(std::string name, double mu_r, std::string source);
  static Material make_magnet(std::string name, double B_r, double mu_r, std::string source);
  static Material make_soft(std::string name, std::shared_ptr<const BhCurve> curve,
                            std::string source);
};

// "linear", "magnet" or "soft" (the spelling used in case files).
const char* to_string(MaterialKind kind);

} // namespace magfem
