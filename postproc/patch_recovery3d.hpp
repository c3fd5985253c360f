#pragma once
// Superconvergent patch recovery (Zienkiewicz-Zhu SPR) of the potential's field in 3D, per
// region: the smooth H* that the error estimator (error_estimate3d.hpp) and the force error
// estimates compare the element field with.
//
// What is recovered: G = -grad phi, the part of H the FE computes. In reduced regions with
// coils H = H_s - grad phi with H_s the coils' known free-space field; recovering G alone
// keeps the non-polynomial H_s (large near windings) out of the fit, and H* - H_h = G* - G_h
// has nothing of H_s left. In total regions (and without coils) G is H itself.
//
// Why not RecoveredB3D's nodal averages: for order 2 the element field is linear per tet and
// its error at the P2 nodes does not cancel in an average. In 1D, for u = x^3 on a uniform
// mesh, the P2 interpolant's derivative error at both ends of every element is the same
// (+h^2 u'''/12) and at the midpoint -h^2 u'''/24: the averages at the nodes are the element
// values themselves, their quadratic interpolant *is* the element field, and the
// Zienkiewicz-Zhu estimate is zero. The 3D meshes behave alike (less extremely): B* must be
// one order better than B_h for B* - B_h to measure B - B_h. A least-squares fit of a
// polynomial of degree p (the element order; one above the element field's p - 1) to G_h at
// many points of a patch of elements is a local L2 projection: the element-scale oscillation
// of the error (zero mean per element in the 1D example) averages out and the fit carries
// the smooth field to O(h^(p+1)) at the patch's vertex (Zienkiewicz & Zhu 1992, IJNME 33).
//
// Construction: for every mesh vertex v and every region r with a tet at v, the patch is r's
// tets at v (its second ring within r when it has fewer than min_patch_tets, as at region
// edges and corners, where a one-sided patch would extrapolate); a degree-p polynomial in
// (x - x_v) / h is fitted to G_h at the 4 degree-2 rule points of every tet of the patch
// (volume-weighted least squares; a patch whose points do not determine the polynomial
// falls back to a lower degree). Nodal values per (DOF, region): a vertex takes
// its own patch's polynomial, a P2 edge node the mean of its two end vertices' polynomials at
// the node; inside a tet of r, G* interpolates r's nodal values with the element's shape
// functions (isoparametric on curved tets). Like RecoveredB3D, a region never sees another
// region's field.
//
// The open-boundary shell is a region of its own, recovered in its mapped (mesh) coordinates:
// there G = -grad phi is the mesh gradient of the potential, which the radial map makes
// smooth (a dipole's potential becomes cos theta times a quadratic in R2 - r, shell_transform.hpp)
// and which jumps in its radial part at r = R1 (J is not the identity there), so the shell
// never shares a fit with the air. G and G_h there are mesh quantities (the error
// estimate weighs them with the shell's metric); B() is physical and not for shell tets.
// At the shell's outer sphere (infinity, phi = 0) the exact G is normal to the sphere, and
// the metric's tangential part grows like 1 / (R2 - r)^2 towards it: the one-sided fits there
// extrapolate a tangential G* that the metric magnifies (on the magnetized sphere, order 2,
// the shell's estimate was 2.6x its true error in the tets touching R2), so those nodal
// values keep only their radial part.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "postproc/field3d.hpp"
#include "postproc/region_slots.hpp"

namespace magfem {

class PatchRecovery3D {
public:
  // Regions with fewer tets at a vertex take the second ring (see above).
  static constexpr int min_patch_tets = 6;

  // `field` (problem, mesh, DOF map) must outlive this object. threads: 0 = all cores; the
  // result does not depend on the count.
  explicit PatchRecovery3D(const Field3D& field, int threads = 0);

  // Recovered G* = -grad phi* (A/m) at bary of tet t (shell tets: the mesh gradient).
  Eigen::Vector3d G(std::size_t t, const std::array<double, 4>& bary) const;
  // G_h at the four vertices of straight tet t (it is linear there): G_h at bary is
  // sum_i bary_i corners(t)[i]. Not for curved tets.
  const std::array<Eigen::Vector3d, 4>& corners(std::size_t t) const { return corner_[t]; }
  // G* at tet t's DOF nodes (its region's values), in local order; returns their count.
  int nodal_values(std::size_t t, std::array<Eigen::Vector3d, 10>& out) const;
  // The element's own G_h = -grad phi_h (A/m) at bary of tet t: H_h less the coils' H_s in
  // reduced regions.
  Eigen::Vector3d G_h(std::size_t t, const std::array<double, 4>& bary) const;
  // Recovered H* (A/m) at bary of tet t (not a shell tet): G* plus (reduced regions) the
  // coils' H_s at the point.
  Eigen::Vector3d H(std::size_t t, const std::array<double, 4>& bary) const;
  // Recovered B* (T) at bary of tet t (not a shell tet): the region's law applied to H*.
  Eigen::Vector3d B(std::size_t t, const std::array<double, 4>& bary) const;

  const Field3D& field() const { return field_; }
  std::size_t n_slots() const { return value_.size(); }
  // Patches whose fit fell back to a lower degree (too few or coplanar points).
  std::size_t n_degraded() const { return n_degraded_; }

private:
  // H* at bary of tet t, x the point (physical).
  Eigen::Vector3d H_at(std::size_t t, const std::array<double, 4>& bary,
                       const Eigen::Vector3d& x) const;
  void keep_radial_at_infinity(); // n x G* = 0 on the open boundary's outer sphere

  const Field3D& field_;
  RegionSlots slots_;                  // per (DOF, region), the shell's too
  std::vector<Eigen::Vector3d> value_; // G* of each slot, A/m
  std::vector<std::array<Eigen::Vector3d, 4>> corner_; // G_h at the vertices, straight tets
  std::size_t n_degraded_ = 0;
};

} // namespace magfem
