#pragma once
// A plane section through the 3D domain over which the flux of B is integrated: a rectangle
// (sides size_u along frame.u and size_v along frame.v, centred on frame.center) or a disk
// (radius about frame.center). Metres (the case reader converts). The flux is counted along
// frame.n.
#include <numbers>
#include <string>

#include "postproc/plane_frame.hpp"

namespace magfem {

struct SectionSpec {
  enum class Kind { rectangle, disk };
  std::string name;
  Kind kind = Kind::rectangle;
  PlaneFrame frame;
  double size_u = 0, size_v = 0; // rectangle
  double radius = 0;             // disk
  int line = 0;                  // line in the case file, for messages

  // The nominal area in m^2 (a x b, or pi r^2).
  double area() const {
    return kind == Kind::rectangle ? size_u * size_v : std::numbers::pi * radius * radius;
  }
};

} // namespace magfem
