#pragma once
// A mirror plane that maps two groups of magnets onto themselves, magnet by magnet, up to the
// sign of each magnet's charge: the segment arrays and the compensator prototype are
// symmetric about the plane of their tilt (y = 0). The charge interaction of a magnet pair
// then equals that of its mirror pair, mirrored: the force between mirrored charges is the
// mirrored force, and about a point of the plane the torque (an axial vector) is minus the
// mirrored torque,
//   F_kl = s S F_ij,   T_kl = -s S T_ij,   S = I - 2 n n^T,  s = s_i s_j,
// so the face-pair cubature (pair_interaction.hpp) integrates one pair of each mirrored two.
//
// Detection compares charge distributions, not descriptions: a magnet's "fingerprint" is the
// point charges of a fixed low-order Gauss rule on its faces and volume; magnet k is i's
// mirror image (sign s) when the mirrored points of i are k's points and the charges s times
// k's, to a relative 1e-9. Gauss rules are symmetric, so a mirrored face's nodes are the
// nodes of its image; anything not matched this way (e.g. a segment mirrored onto itself with
// a differently split parameter box) simply finds no mirror and is integrated in full.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "analytic/analytic_magnet.hpp"

namespace magfem {

struct MirrorSymmetry {
  Eigen::Vector3d point;  // on the plane
  Eigen::Vector3d normal; // unit
  // Index of each magnet's image in its own group, and the sign of the image's charge.
  std::vector<int> image_on, image_by;
  std::vector<double> sign_on, sign_by;

  // S v = v - 2 (v.n) n.
  Eigen::Vector3d reflect(const Eigen::Vector3d& v) const;
};

// The first of the planes through `point` normal to x, y, z that maps both groups onto
// themselves as above, or nullopt. Throws std::invalid_argument for invalid shapes.
std::optional<MirrorSymmetry> find_mirror_symmetry(const std::vector<AnalyticMagnet>& on,
                                                   const std::vector<AnalyticMagnet>& by,
                                                   const Eigen::Vector3d& point);

} // namespace magfem
