#pragma once
// A section over which the flux of B is integrated. 3D: a plane rectangle (sides size_u along
// frame.u and size_v along frame.v, centred on frame.center) or disk (radius about
// frame.center), the flux counted along frame.n. 2D and axisymmetric: a straight line from
// start to end (planar: the strip it sweeps through the depth; axisymmetric: the surface it
// sweeps about the axis), the flux counted along the direction start -> end turned 90 degrees
// counter-clockwise (z x t: a line from the axis outwards counts flux along +z). Metres (the
// case reader converts).
#include <numbers>
#include <string>

#include "postproc/plane_frame.hpp"

namespace magfem {

struct SectionSpec {
  enum class Kind { rectangle, disk, line };
  std::string name;
  Kind kind = Kind::rectangle;
  PlaneFrame frame;
  double size_u = 0, size_v = 0;                                                  // rectangle
  double radius = 0;                                                              // disk
  Eigen::Vector2d start = Eigen::Vector2d::Zero(), end = Eigen::Vector2d::Zero(); // line
  int line = 0; // line in the case file, for messages

  // The nominal area in m^2 (a x b, or pi r^2) of a plane section (a line's depends on the
  // case: section_flux2d.hpp).
  double area() const {
    return kind == Kind::rectangle ? size_u * size_v : std::numbers::pi * radius * radius;
  }
};

} // namespace magfem
