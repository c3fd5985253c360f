#pragma once
// Zonal harmonic expansions of the field of an axisymmetric coil about a point of its axis:
// outside the smallest sphere about that point that holds the bundle (exterior) and inside the
// largest sphere free of it (interior) the field is -grad of a scalar potential
// sum_m c_m r^{-(m+1)} P_m or sum_m c_m r^m P_m. Evaluating a few dozen terms costs far less
// than integrating the bundle, and most field points of a mesh lie in one of the two regions.
// The exterior expansion is centred where the enclosing sphere is smallest (for the ring of a
// spherical coil, the ring's own centre, not the sphere's), the interior one at the origin.
//
// The coefficients come from the on-axis field of the bundle's loops, integrated exactly; see
// zonal_expansion.cpp.
#include <vector>

#include "mesh/coil3d.hpp"
#include "sources/loop_field.hpp"

namespace magfem {

class ZonalExpansion {
public:
  enum class Kind { exterior, interior };

  ZonalExpansion() = default;
  // `coefficients[m]` (m >= 1; [0] unused) are normalized by the radius R of the region:
  //   exterior (r > R): H_r = r^-2 sum (m+1) c_m q^m P_m(cos t), H_t = r^-2 sum c_m q^m P_m^1,
  //                     q = R / r;
  //   interior (r < R): H_r = -sum m c_m q^(m-1) P_m(cos t),   H_t = sum c_m q^(m-1) P_m^1,
  //                     q = r / R;
  // with P_m^1 = sin t P_m'(cos t), t the polar angle from the axis. A point is evaluated only if
  // the tail of the series is bounded by `tolerance` times the leading (dipole or uniform) term
  // within `max_terms` terms; the bound uses the stored coefficients' magnitudes.
  // The expansion is about the axis point z = center.
  ZonalExpansion(Kind kind, double center, double radius, std::vector<double> coefficients,
                 double tolerance, int max_terms);

  bool empty() const { return coefficients_.size() < 2; }
  Kind kind() const { return kind_; }
  double center() const { return center_; }
  double radius() const { return radius_; }
  // Largest q = R/r (exterior) or r/R (interior) at which the series is used.
  double q_limit() const { return q_limit_; }
  const std::vector<double>& coefficients() const { return coefficients_; }

  // Field at meridian point (rho, z); false (h untouched) if the point is outside the region
  // where the series meets the tolerance.
  bool evaluate(double rho, double z, MeridianField& h) const;

private:
  Kind kind_ = Kind::exterior;
  double center_ = 0;
  double radius_ = 0;
  double tolerance_ = 0;
  double q_limit_ = 0;
  int max_terms_ = 0;
  std::vector<double> coefficients_;
  std::vector<double> radial_; // (m+1) c_m (exterior) or -m c_m (interior): H_r's factors
  std::vector<double> tail_;   // tail_[m] = max_{k >= m} 2 (k+1) |c_k| / |c_1|
};

// A coaxial loop of radius a at height z0 carrying `current` (A): one node of a quadrature of
// the bundle's cross-section, the weight folded into the current.
struct LoopSample {
  double a, z0, current;
};

// Exterior coefficients about z = center, normalized by `radius`, m = 0..n_terms ([0] unused).
// a^2 R0^(m-1) P_m'(t0) is a polynomial of degree m + 1 in (a, z0 - center), so a tensor
// Gauss rule of that degree over the cross-section makes them exact.
std::vector<double> exterior_coefficients(const std::vector<LoopSample>& loops, double center,
                                          double radius, int n_terms);

// Interior coefficients about the origin for a bundle carrying `current` (A, total through the
// cross-section), normalized by the radius of the largest sphere free of the bundle
// (r_inner for both shapes), m = 0..n_terms.
std::vector<double> spherical_coil_interior_coefficients(const SphericalCoil& c, double current,
                                                         int n_terms);
std::vector<double> solenoid_interior_coefficients(const Solenoid& c, double current, int n_terms);

} // namespace magfem
