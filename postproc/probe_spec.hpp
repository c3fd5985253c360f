#pragma once
// Where the user wants the field sampled. Coordinates in metres, angles in radians (the case
// reader converts); the CSV writer converts back to the case's length unit and degrees.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "postproc/plane_frame.hpp"

namespace magfem {

struct ProbeSpec {
  enum class Kind { line, circle, sphere, points, plane };
  std::string name;
  Kind kind = Kind::line;
  // line: `points` samples from start to end inclusive
  Eigen::Vector3d start = Eigen::Vector3d::Zero(), end = Eigen::Vector3d::Zero();
  // circle (2D, in the xy-plane): `points` samples from angle_start, spaced evenly to
  // angle_end (exclusive when the range is a full turn, inclusive otherwise)
  // sphere patch (3D): theta and phi ranges with `theta_steps`/`phi_steps` samples inclusive
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0;
  double angle_start = 0, angle_end = 0;
  double theta_min = 0, theta_max = 0, phi_min = 0, phi_max = 0;
  int points = 0;
  // points (3D): an explicit list of sample points
  std::vector<Eigen::Vector3d> point_list;
  int theta_steps = 0, phi_steps = 0;
  // plane (3D): a u_steps x v_steps grid over the rectangle size_u x size_v centred on
  // plane.center (sides along plane.u and plane.v), both ends included (one step: the
  // centre line); u the outer loop
  PlaneFrame plane;
  double size_u = 0, size_v = 0;
  int u_steps = 0, v_steps = 0;
  int line = 0; // line in the case file, for messages
};

} // namespace magfem
