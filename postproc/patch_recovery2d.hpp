#pragma once
// Superconvergent patch recovery (Zienkiewicz-Zhu SPR) of B in 2D and axisymmetric solutions,
// per region: what the probes read (probes2d.hpp), as PatchRecovery3D is in 3D.
//
// Why not the element field: B_h = curl A_h is discontinuous across elements and O(h^p) for
// order p; why not Field2D::recovered_B's nodal averages: they mix materials at region
// boundaries (B_t jumps by mu_r) and, for order 2, do not gain an order (the P2 element
// field's derivative error at an element's DOF nodes does not cancel in an average; see
// patch_recovery3d.hpp). A least-squares fit of a polynomial of the element's degree p to
// B_h at interior points of a patch of elements is a local L2 projection: the element-scale
// oscillation of the error averages out and the fit carries the smooth field to O(h^(p+1))
// (Zienkiewicz & Zhu 1992, IJNME 33). Cylinder2D.ConvergenceRatesMatchTheory asserts the
// orders on the exact diametric cylinder.
//
// Construction: for every mesh vertex v and every region r with a triangle at v, the patch
// is r's triangles at v (their second ring within r when fewer than min_patch_triangles, as
// at region corners, where a one-sided patch would extrapolate); a degree-p polynomial in
// (x - x_v) / h is fitted to B_h at the 3 interior points of the degree-2 rule of every
// triangle of the patch (area-weighted least squares; a patch whose points do not determine
// the polynomial falls back to a lower degree). Nodal values per (DOF, region): a vertex
// takes its own patch's polynomial, a P2 edge node the mean of its two end vertices'
// polynomials at the node; inside a triangle of r, B* interpolates r's nodal values with the
// element's shape functions. A region never sees another region's field. On the axis of an
// axisymmetric case B_r is set to its exact zero.
//
// The open-boundary shell is a region of its own, recovered in its mapped (mesh) coordinates
// (Field2D::B there is the curl of A in those coordinates, smooth under the radial map): the
// error estimate (error_estimate2d.hpp) weighs B* - B_h there with the shell's metric. Probes
// never read it (they sample the physical domain).
#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "postproc/field2d.hpp"
#include "postproc/patch_fit.hpp"
#include "postproc/region_slots.hpp"

namespace magfem {

class PatchRecovery2D {
public:
  // Regions with fewer triangles at a vertex take the second ring (see above). Three, not
  // more: at 4 the outline's vertices (2 or 3 triangles) took the second ring, whose wider fit
  // smoothed over corners and the winding's edges (the error estimate's effectivity on the
  // iron-cored solenoid, tests/pipeline/test_error_estimate2d.cpp: 1.06 -> 1.82).
  static constexpr int min_patch_triangles = 3;

  // `field` (problem, mesh, DOF map) must outlive this object.
  explicit PatchRecovery2D(const Field2D& field);

  const Field2D& field() const { return field_; }

  // Recovered B* (T) at bary of triangle t: planar (Bx, By), axisymmetric (Br, Bz); in a
  // shell triangle the mapped coordinates' B, as Field2D::B gives it there.
  Eigen::Vector2d B(std::size_t t, const std::array<double, 3>& bary) const;

  std::size_t n_slots() const { return value_.size(); }
  // Patches whose fit fell back to a lower degree (too few or collinear points).
  std::size_t n_degraded() const { return n_degraded_; }

private:
  // P2 edge nodes: the mean of their two end vertices' fits (fits: per vertex slot).
  void set_edge_values(const std::vector<PatchFit<2>>& fits);
  // Axisymmetric: B_r = 0 on the axis (A_phi = 0 there, curl2d.hpp), which a one-sided fit of
  // the odd B_r misses by round-off of the fit (~1e-7 T).
  void keep_axial_on_axis();

  const Field2D& field_;
  RegionSlots slots_;                  // per (DOF, region), the shell's too
  std::vector<Eigen::Vector2d> value_; // B* of each slot, T
  std::size_t n_degraded_ = 0;
};

} // namespace magfem
