#pragma once
// Magnetic charge distributions of one magnet, split into faces (surface charge sigma = M.n)
// and, for non-uniform magnetization, its volume (rho_m = -div M). Each face or volume is a
// map from a parameter box (angles, radii, lengths) to global space; quadrature over any
// sub-box turns it into point charges q = sigma dA (A m) or rho_m dV. The charge model and the
// charge-interaction force share these building blocks.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "analytic/analytic_magnet.hpp"

namespace magfem {

struct PointCharge {
  Eigen::Vector3d x; // global position, metres
  double q;          // charge, A m (sigma dA or rho_m dV)
};

// Equivalent surface current element K dA = (M x n) dA (A m), for magnetizations without
// curl (parallel and radial), whose B is then the Biot-Savart field of the face currents.
struct PointCurrent {
  Eigen::Vector3d x; // global position, metres
  Eigen::Vector3d j; // K dA, A m
};

// Gauss-Legendre rule on [-1, 1].
struct GaussRule {
  std::vector<double> nodes, weights;
  explicit GaussRule(int n);
  int size() const { return static_cast<int>(nodes.size()); }
};

// Box in parameter space; unused dimensions have lo = hi = 0.
struct ParamBox {
  std::array<double, 3> lo{}, hi{};
};

enum class ChargeDomainKind {
  sphere_face,     // rho = fixed; params (theta, phi)
  cone_face,       // theta = fixed; params (rho, phi)
  meridian_face,   // phi = fixed; params (rho, theta)
  sphere_volume,   // params (rho, theta, phi)
  cap_face,        // cylinder z = fixed; params (r, alpha)
  mantle_face,     // cylinder r = fixed; params (alpha, z)
  cylinder_volume, // params (r, alpha, z)
  box_face,        // x_axis = fixed; params the two other coordinates in cyclic order
  box_volume       // params (x, y, z)
};

// One face or volume of one magnet. `orient` is +1 or -1 so that the area vector points out
// of the magnet. Magnetization and placement are copied from the magnet.
struct ChargeDomain {
  ChargeDomainKind kind = ChargeDomainKind::sphere_face;
  double fixed = 0;
  double orient = 1;
  int axis = 0; // box faces only
  int dim = 2;
  ParamBox box;
  Placement placement;
  Magnetization magnetization;
  double M0 = 0; // A/m, B_r / mu0

  // Global point at parameters u.
  Eigen::Vector3d point(const std::array<double, 3>& u) const;
  // Appends the point charges of the tensor Gauss rule on `sub` (a sub-box of `box`).
  void quadrature(const ParamBox& sub, const GaussRule& rule, std::vector<PointCharge>& out) const;
  // Surface domains only: the current elements (M x dA) of the same rule.
  void current_quadrature(const ParamBox& sub, const GaussRule& rule,
                          std::vector<PointCurrent>& out) const;
};

// Throws std::invalid_argument (naming the magnet) for empty or inverted ranges, angles
// outside [0, pi] x [phi_min, phi_min + 2 pi], negative B_r or a non-unit parallel direction.
void check_shape(const AnalyticMagnet& magnet);

// The faces (and the volume if div M != 0) of a magnet carrying charge (checked first). Faces whose
// charge vanishes identically (e.g. cone faces of a radially magnetized segment) and faces of zero
// area (theta = 0 cones, the coinciding meridian faces of a full revolution) are dropped.
std::vector<ChargeDomain> charge_domains(const AnalyticMagnet& magnet);

// The faces of a magnet carrying surface current M x n (no volume current: curl M = 0 for
// parallel and radial patterns). For radial magnetization about the segment's own centre
// these are the cone and meridian faces only, which avoids the volume charge altogether.
std::vector<ChargeDomain> current_domains(const AnalyticMagnet& magnet);

// Sub-box geometry for adaptive quadrature: approximate centre and bounding radius of the
// image of `sub`, and the parameter axis along which the image is longest.
struct BoxExtent {
  Eigen::Vector3d centre;
  double radius = 0;
  int longest_axis = 0;
};
// For surfaces, `grid` (if given) receives the global images of the 3 x 3 parameter grid
// {lo, mid, hi}^2 that the extent samples, index 3 i + j.
BoxExtent box_extent(const ChargeDomain& domain, const ParamBox& sub,
                     std::array<Eigen::Vector3d, 9>* grid = nullptr);

// Which parameters of the domain are angles (the others are lengths).
std::array<bool, 3> angular_parameters(const ChargeDomain& domain);

// The domain's box cut into a grid whose angular parameters span at most max_angle each:
// Gauss rules in an angle converge at a rate set by the complex distance ln(D/a) of the
// singularity, which for large arcs is much less than the chord distance suggests.
std::vector<ParamBox> root_boxes(const ChargeDomain& domain, double max_angle);

// Distance / box radius beyond which a Gauss rule of `order` points per direction integrates
// a field with a 1/r^2-type singularity at that distance to about `tolerance` (Bernstein
// ellipse: cosh(ln(1/tol) / (2 order)), at least 1).
double acceptance_ratio(double tolerance, int order);

// Halves `sub` along `axis`.
std::array<ParamBox, 2> split_box(const ParamBox& sub, int axis);

// True if global point x lies inside the magnet (closed set).
bool magnet_contains(const AnalyticMagnet& magnet, const Eigen::Vector3d& x);

} // namespace magfem
