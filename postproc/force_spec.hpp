#pragma once
// Which forces and torques the user wants from a solved field. Metres (the case reader
// converts). Torque is about `torque_point`; in 2D per unit length (times the stack length
// when the case gives one).
#include <string>
#include <vector>

#include <Eigen/Core>

namespace magfem {

struct ForceSpec {
  enum class Kind {
    circle,  // 2D: Maxwell stress tensor on a circle in air (force on what it encloses)
    band,    // 2D: Arkkio's band average of the stress tensor over an air annulus
    lorentz, // 2D: integral of J x B over current-carrying regions
    sphere   // 3D: Maxwell stress tensor on a sphere in air (force on what it encloses)
  };
  std::string name;
  Kind kind = Kind::sphere;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0;                // circle, sphere
  double r_inner = 0, r_outer = 0;  // band
  std::vector<std::string> regions; // lorentz
  Eigen::Vector3d torque_point = Eigen::Vector3d::Zero();
  double check_radius = 0; // circle, sphere: also evaluate this radius and report the spread
  int line = 0;            // line in the case file, for messages
};

} // namespace magfem
