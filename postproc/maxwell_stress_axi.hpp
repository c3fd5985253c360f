#pragma once
// Axisymmetric Maxwell stress: the axial force on everything inside a closed surface of
// revolution, given by its meridian contour in the r-z half plane (x = r, y = z). A contour
// that starts and ends on the axis closes there (the axis sweeps no area: its weight 2 pi r
// is zero). Quadrature points and weights for maxwell_stress_sum (maxwell_stress.hpp), whose
// z component is then
//   F_z = oint (1/mu0) (B_z (B . n) - |B|^2 n_z / 2) 2 pi r dl;
// the r component and the torque average out over the turn and are not meaningful.
#include <vector>

#include <Eigen/Core>

#include "postproc/maxwell_stress.hpp"

namespace magfem {

// polyline: vertices in metres, counter-clockwise around the enclosed region (outward normal
// on the right of the direction of travel), each segment cut into n_panels panels of `order`
// Gauss-Legendre points. Points are (r, 0, z), normals (n_r, 0, n_z), weights 2 pi r dl.
std::vector<SurfacePoint> revolved_contour_quadrature(const std::vector<Eigen::Vector2d>& polyline,
                                                      int n_panels, int order);

// The meridian contour around the box [r_min, r_max] x [z_min, z_max] (r_min = 0: the contour
// starts and ends on the axis, the surface is a closed can; else a closed ring).
std::vector<Eigen::Vector2d> box_contour(double r_min, double r_max, double z_min, double z_max);

// F_z (N) through the contour with B from the callback (B_r, B_z in tesla at (r, z)).
double maxwell_stress_axial_force(const FieldFunction2D& B,
                                  const std::vector<Eigen::Vector2d>& polyline, int n_panels = 256,
                                  int order = 4);

} // namespace magfem
