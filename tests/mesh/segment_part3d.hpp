#pragma once
// A spherical-segment part (radii in metres, angles in radians) for the 3D mesher's tests.
#include <string>

#include "mesh/geometry3d.hpp"

namespace magfem::test {

inline Part3D segment(const std::string& name, double r1, double r2, double t1, double t2,
                      double p1, double p2) {
  Part3D p;
  p.name = name;
  p.shape = SphericalSegment{r1, r2, t1, t2, p1, p2};
  return p;
}

} // namespace magfem::test
