#pragma once
// Spherical harmonic model of a spherical-shell magnet array (thesis sec. 3.6, extended):
// magnets that are SphericalSegments of one shell R_i..R_o about the origin (any theta/phi
// ranges: full shells, hemispheres, uneven P_theta x P_phi, gaps are non-magnetized), each
// with parallel or radial magnetization, mu_r = 1, in free space or enclosed by an infinitely
// permeable sphere at R_s > R_o (psi = 0 there). The magnetization is expanded in vector
// spherical harmonics (harmonic_expansion.hpp) and the scalar potential solved per degree in
// the three regions (harmonic_radial.hpp).
//
// Differences from the thesis: the volume charges -div M (including the charge sheets
// between segments) and radial magnetization are included, where eqs. 3.104-3.108 keep only
// the surface charges at R_i and R_o (on the benchmark that omission changes B_rho on r56 by
// 0.38 % rms pointwise, yet only -0.03 % in the eq. 3.117 measure); Legendre functions are
// fully normalized with stable recurrences and radial powers are ratios <= 1, so any degree
// works (the thesis overflowed beyond 149 harmonics, 122 bounded).
//
// Convergence: outside the shell the degree-n terms fall like (R_o/rho)^n / n, in the cavity
// like (rho/R_i)^n / n; at 1 mm from a 55 mm shell n_max = 600 gives ~5e-7 and 800 ~1e-8
// relative rms (against the charge model). In the magnet itself convergence is only
// algebraic (Gibbs at segment boundaries).
//
// Field evaluation groups points that share (rho, theta) (e.g. a probe grid): per group the
// degree sums are done once per order m, after which each point costs O(n_max).
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "analytic/analytic_magnet.hpp"
#include "analytic/harmonic_expansion.hpp"
#include "analytic/harmonic_radial.hpp"

namespace magfem {

// The shell a magnet list describes: common radii and the magnetized segments (A/m).
struct ShellArray {
  double r_inner = 0, r_outer = 0;
  std::vector<ShellSegmentSource> segments;
};
// Validates and converts (same rules and messages as HarmonicModel); non-magnetized magnets
// (Pattern::none) are dropped.
ShellArray to_shell_array(const std::vector<AnalyticMagnet>& magnets);

struct HarmonicOptions {
  int n_max = 200;                        // highest degree n (orders m = 0..n)
  std::optional<double> permeable_radius; // metres: infinitely permeable sphere R_s > R_o
  double quadrature_scale = 1.0;          // multiplies the theta quadrature nodes (>= 1)
  int n_threads = 0;                      // 0: std::thread::hardware_concurrency()
};

class HarmonicModel {
public:
  // Throws std::invalid_argument (message names the magnet) for lists it cannot represent:
  // non-spherical shapes, different radii, shells not centred at the origin or rotated,
  // radial centres away from the origin, R_s <= R_o, n_max < 1.
  HarmonicModel(const std::vector<AnalyticMagnet>& magnets, HarmonicOptions options);
  // The same with the boundary given as PermeableSphere (the charge model's input): at most
  // one, centred at the origin, enclosing the magnets.
  HarmonicModel(const std::vector<AnalyticMagnet>& magnets,
                const std::vector<PermeableSphere>& spheres, HarmonicOptions options);

  // Flux density (tesla) at global points. Inside the magnets B = mu0 (H + M) with the exact
  // M of the containing segment. Points beyond R_s (inside the iron) are rejected with
  // std::domain_error.
  Eigen::Vector3d B(const Eigen::Vector3d& x) const;
  std::vector<Eigen::Vector3d> B(const std::vector<Eigen::Vector3d>& x) const;
  // Field strength H = B / mu0 - M (A/m), same rules.
  std::vector<Eigen::Vector3d> H(const std::vector<Eigen::Vector3d>& x) const;
  // Magnetization (A/m) at x: that of the segment containing x (faces belong to one side).
  Eigen::Vector3d magnetization(const Eigen::Vector3d& x) const { return magnetization_at(x); }

  int n_max() const { return options_.n_max; }
  double r_inner() const { return r_inner_; }
  double r_outer() const { return r_outer_; }
  const ShellExpansion& expansion() const { return expansion_; }
  double setup_seconds() const { return setup_seconds_; } // expansion time

private:
  HarmonicModel(ShellArray shell, HarmonicOptions options);
  struct Group; // points sharing (rho, theta)
  void evaluate_group(const Group& group, const std::vector<Eigen::Vector3d>& x,
                      std::vector<Eigen::Vector3d>& out) const;
  Eigen::Vector3d magnetization_at(const Eigen::Vector3d& x) const; // A/m

  HarmonicOptions options_;
  double r_inner_ = 0, r_outer_ = 0;
  std::vector<ShellSegmentSource> segments_;
  ShellExpansion expansion_;
  ShellRadialSolution radial_;
  NormalizedLegendre legendre_;
  double setup_seconds_ = 0;
};

} // namespace magfem
