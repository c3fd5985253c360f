#pragma once
// Method of images for infinitely permeable spheres (thesis sec. 3.5) by Kelvin inversion.
// A charge q at x' seen through a sphere (centre c, radius k) has its image at
//   x'' = c + k^2 (x' - c) / |x' - c|^2   with charge   q'' = -q k / |x' - c|.
// Since inversion scales areas by (k/|x'-c|)^4 and volumes by (k/|x'-c|)^6, this is the
// thesis's density scaling sigma'' = (k/rho'')^3 sigma and rho_m'' = (k/rho'')^5 rho_m
// (eqs. 3.82/3.83), with the sign made explicit: the image makes the scalar potential zero on
// the sphere, so tangential H vanishes there (tested). Two or more spheres need chains of
// inversions (an image in one sphere is imaged again in the other).
#include <vector>

#include <Eigen/Core>

#include "analytic/analytic_magnet.hpp"
#include "analytic/charge_source.hpp"

namespace magfem {

struct Inversion {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0; // k, metres
};

// Composition of inversions, applied in order (chain[0] first). Empty = identity.
class ImageMap {
public:
  ImageMap() = default;
  explicit ImageMap(std::vector<Inversion> chain) : chain_(std::move(chain)) {}

  bool is_identity() const { return chain_.empty(); }
  const std::vector<Inversion>& chain() const { return chain_; }

  // Image of a point charge (position and charge).
  PointCharge apply(const PointCharge& source) const;
  // The point whose image is x (each inversion is an involution: apply in reverse order).
  Eigen::Vector3d preimage(const Eigen::Vector3d& x) const;

private:
  std::vector<Inversion> chain_;
};

Eigen::Vector3d invert(const Inversion& inv, const Eigen::Vector3d& x);

// Sequences of sphere indices of length 1..order with no index repeated consecutively
// (imaging twice in the same sphere returns the original). One sphere gives {{0}}; two
// spheres with order 2 give {0}, {1}, {0,1}, {1,0}: the thesis's "4 images".
std::vector<std::vector<int>> image_chains(int n_spheres, int order);

} // namespace magfem
