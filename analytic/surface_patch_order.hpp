#pragma once
// Gauss orders for a pair of surface boxes from where the kernel's singularity lies in the
// complex parameter plane, rather than from bounding spheres alone.
//
// The face-pair cubature (pair_interaction.hpp) integrates K(x_A(u) - y) over a box A of a
// face, u in [-1, 1]^2, for every y of a box B. Near A, x_A(u) ~ c + h_0 u_0 t_0 + h_1 u_1 t_1
// (tangents t_k, half-lengths h_k). Along direction k, with the other parameter real in
// [-1, 1], |x_A - y|^2 = (h_k u_k - a)^2 + b^2 vanishes at u_k = (a +- i b) / h_k, where a is
// y's offset along t_k and b its distance from the line swept by the other direction. A
// Gauss rule of n points then converges like rho^(-2n), rho the Bernstein-ellipse parameter
// of z = (a + i b) / h_k, |z + sqrt(z^2 - 1)|. The bounding-sphere rule takes the worst case
// b = 0 (B in A's plane): right for coplanar neighbours, but for the parallel faces across a
// narrow gap (b = gap) it forces boxes a few times smaller than the gap, where the
// imaginary offset allows boxes about as large as the gap: ~10x fewer kernel evaluations on
// a 2 mm gap between spherical shells.
//
// Curvature is accounted as a margin: `sag` is the 3 x 3 samples' largest deviation from the
// affine model, and the distances a and b are reduced by 8 sag_A + sag_B (A's quadratic
// deviation continued to the singular parameter u* grows like |u*|^2, |u*| <~ 2.5 where the
// orders stay within the cubature's maximum; B's image bulges at most its sag beyond its
// samples). A smaller factor (sag_A max(1, |u*|^2)) was measured to lose accuracy on the
// segment arrays (1.7e-8 of |F| against 1.2e-8 with bounding spheres alone); 8 gives 9e-9.
// Where the margin would exceed a quarter of the distance |a + i b|, the model is not
// trusted and the caller keeps the bounding-sphere order.
#include <array>
#include <optional>

#include <Eigen/Core>

#include "analytic/charge_source.hpp"

namespace magfem {

// Affine model of the image of a surface box: x(u) ~ centre + sum_k half[k] u_k tangent[k].
struct SurfacePatch {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  std::array<Eigen::Vector3d, 2> tangent{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  std::array<double, 2> half{0, 0};       // metres
  double sag = 0;                         // metres: largest deviation of the samples from the model
  std::array<Eigen::Vector3d, 9> samples; // global images of the 3 x 3 grid {lo, mid, hi}^2
  bool valid = false; // false for volumes, degenerate or skewed parameterizations
};

// The model of a surface box from the global images of its 3 x 3 parameter grid
// {lo, mid, hi}^2, index 3 i + j (box_extent's `grid`).
SurfacePatch surface_patch(const std::array<Eigen::Vector3d, 9>& grid);
// The same for `sub` (a sub-box of a surface domain's box); valid = false for volumes.
SurfacePatch surface_patch(const ChargeDomain& domain, const ParamBox& sub);

// Bernstein-ellipse parameter (>= 1) of the point z = x + i y relative to [-1, 1].
double bernstein_parameter(double x, double y);

// The smallest Bernstein parameter, over both directions of a and over all points of b, of
// the singularity of the kernel between the two patches, expressed as the equivalent real
// distance ratio cosh(ln rho) that gauss_order() takes; nullopt where the affine model is not
// trusted (see the header comment).
std::optional<double> patch_pair_rho(const SurfacePatch& a, const SurfacePatch& b);

} // namespace magfem
