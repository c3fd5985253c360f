#pragma once
// Single-valued, monotone B-H curve of a soft magnetic material (anhysteretic).
//
// Built from a table (H in A/m, B in T), starting at (0, 0) (inserted if absent).
// Interpolation is monotone (no overshoot between points) with a derivative consistent with
// the interpolant; beyond the last point the curve continues with slope mu0 (the material is
// saturated and behaves like vacuum on top of its saturation polarization).
// Both directions are provided because the 2D A-formulation needs H(B) and the 3D scalar
// potential formulation needs B(H).
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace magfem {

// What BhCurve's constructor throws: a std::invalid_argument that also carries the 0-based
// index of the offending row, so that a parser can point at that row's file line and field.
class BhTableError : public std::invalid_argument {
public:
  BhTableError(std::size_t row, const std::string& message)
      : std::invalid_argument("B-H table row " + std::to_string(row) + ": " + message), row_(row),
        reason_(message) {}
  std::size_t row() const { return row_; }
  const std::string& reason() const { return reason_; } // without the "row i" prefix

private:
  std::size_t row_;
  std::string reason_;
};

// Physical plausibility of a table a user gives (the case file's `bh`, a `bh_file`), beyond
// what the interpolation needs (BhCurve's checks): throws BhTableError naming the first row
// whose polarization B - mu0 H is above 3 T. No material has one (FeCo alloys saturate near
// 2.45 T); mostly the table was given as [B, H], or B in gauss, and the message says so
// ("columns swapped? B must be in T and H in A/m, as [H, B]"). The bound is on J, not B,
// because a table may run on into saturation, where B keeps growing as mu0 H. Curves built
// in code (tests, straight-line fixtures) may go beyond it.
void check_bh_table_plausible(const std::vector<double>& h_Apm, const std::vector<double>& b_T);

class BhCurve {
public:
  // Throws std::invalid_argument with a message naming the first bad row (0-based index into
  // the given vectors) when the table is not usable: sizes differ, fewer than 2 points,
  // H or B not strictly increasing, negative values, a segment slope below mu0 by more than
  // 0.1 % (non-physical: dB/dH >= mu0 must hold for a ferromagnet). Messages end with the
  // likely cause ("... B must be in T and H in A/m, as [H, B]"). Tables a user gives are also
  // checked by check_bh_table_plausible.
  // Callers that read the table from a file turn this into an InputError with file, line and
  // field.
  // Rows with no specific culprit (sizes differ, fewer than 2 points) name row 0.
  // The thrown type is BhTableError (a std::invalid_argument).
  BhCurve(std::vector<double> h_Apm, std::vector<double> b_T);

  // Negative arguments are accepted: the curve is odd (b_of_h(-h) = -b_of_h(h), likewise
  // h_of_b) and the derivatives are even.
  double b_of_h(double h) const; // h >= 0
  double dbdh(double h) const;
  double h_of_b(double b) const; // b >= 0
  double dhdb(double b) const;
  // Stored energy density integral_0^|b| h(b') db' (J/m^3): 8-point Gauss-Legendre on each
  // piece between the table's B values (the curve is smooth between them, not across them, nor
  // across the last one where the extrapolation begins).
  double energy_density(double b) const;

  // Reluctivity form used by B-formulations: nu(b2) = h(b)/b, b = sqrt(b2), and its
  // derivative with respect to b2 (finite as b -> 0).
  void nu_of_b2(double b2, double& nu, double& dnu_db2) const;
  // Permeability form used by H-formulations: mu(h2) = b(h)/h and d mu / d(h2).
  void mu_of_h2(double h2, double& mu, double& dmu_dh2) const;

  // The table as used, with (0, 0) inserted when the input did not start there.
  const std::vector<double>& h_table() const { return h_; }
  const std::vector<double>& b_table() const { return b_; }
  // dB/dH at H = 0 in H/m (the permeability the curve starts with; >= mu0).
  double initial_slope() const { return slope_b_.front(); }
  // The largest secant permeability B/H over the table's points in H/m (>= initial_slope).
  double peak_permeability() const;

private:
  std::vector<double> h_, b_;
  // Implementation detail (e.g. monotone cubic slopes); see bh_curve.cpp.
  std::vector<double> slope_b_; // dB/dH at the table points

  std::size_t interval_of_h(double h) const; // k with h_[k] <= h < h_[k+1], h < h_.back()
  std::size_t interval_of_b(double b) const;
  void hermite(std::size_t k, double h, double& b, double& dbdh) const; // on interval k
  // B and dB/dH at h >= 0, extrapolation included.
  void evaluate(double h, double& b, double& dbdh) const;
  // H and dB/dH (at that H) for b >= 0, extrapolation included.
  void invert(double b, double& h, double& dbdh) const;
  // mu = B/H and d mu/d(H^2) from a point of the curve and its slope there.
  void secant_permeability(double h, double b, double dbdh, double& mu, double& dmu_dh2) const;
};

} // namespace magfem
