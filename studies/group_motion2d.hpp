#pragma once
// A rigid motion of a group of regions of a 2D case: what the planar sweep turns or moves and
// the axisymmetric sweep moves along the axis. The regions with `group: NAME` are carried,
// their shapes and magnetizations alike (a parallel magnetization turns with the body, a
// radial one's centre goes with it); nothing else moves. One motion for every 2D sweep, so
// that a rotation and a translation cannot move different things.
#include <string>

#include "casefile/case_spec.hpp"

namespace magfem {

// x -> center + R(angle) (x - center) + shift (metres; counter-clockwise turn in the plane,
// which is the r-z half plane in axisymmetric cases).
struct RigidMotion2D {
  double angle_rad = 0;
  Vec2 center = Vec2::Zero();
  Vec2 shift = Vec2::Zero();
  Vec2 at(const Vec2& x) const;
};

// The case with every region of `group` carried by `motion`. Throws InputError naming
// `option` (the command line's --rotate or --move) if no region is in the group.
CaseSpec move_group2d(const CaseSpec& spec, const std::string& group, const RigidMotion2D& motion,
                      const std::string& option);

} // namespace magfem
