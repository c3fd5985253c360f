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
    lorentz, // integral of J x B over current-carrying regions (2D) or coils (3D)
    sphere,  // 3D: Maxwell stress tensor on a sphere in air (force on what it encloses)
    box,     // 3D: Maxwell stress tensor on an axis-aligned box surface in air
    contour  // axisymmetric: stress tensor on the revolved box around a region, `margin` out
  };
  std::string name;
  Kind kind = Kind::sphere;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0;                // circle, sphere
  double r_inner = 0, r_outer = 0;  // band
  Eigen::Vector3d size = Eigen::Vector3d::Zero();       // box edge lengths
  Eigen::Vector3d check_size = Eigen::Vector3d::Zero(); // box: second surface (0 = none)
  std::vector<std::string> regions; // lorentz: regions (2D) or coils (3D)
  Eigen::Vector3d torque_point = Eigen::Vector3d::Zero();
  double check_radius = 0; // circle, sphere: also evaluate this radius and report the spread
  double margin = 0;       // contour: distance between the region's bounding box and the contour
  int line = 0;            // line in the case file, for messages
};

} // namespace magfem
