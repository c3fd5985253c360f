#pragma once
// Magnet arrangements that the face-pair interaction (analytic/pair_interaction.hpp) is
// timed and tested on, built in code so that the benchmark and the tests share them:
//  - a spherical coupling of two segment arrays (the thesis's 32-magnet benchmark as a rotor,
//    tilted, inside a hemispherical 2 x 8 array: a net force as well as a torque),
//  - the gravity-compensator prototype (ch. 6): a hemisphere inside radially standing
//    cylinders (examples/3d/compensator_prototype_height_study.yaml states the layout),
//  - two axially magnetized cylinders side by side.
#include <vector>

#include "analytic/analytic_magnet.hpp"

namespace magfem {

struct InteractionCase {
  const char* name;
  std::vector<AnalyticMagnet> on, by; // force and torque on `on`, about the origin
};

// A p_theta x p_phi array of spherical segments r_inner..r_outer over theta 0..theta_max,
// parallel magnetization pointing at each segment's centre with alternating sign (the
// benchmark's `parallel_alternating, convention: centre`), placed by `placement`.
std::vector<AnalyticMagnet> segment_array(double r_inner, double r_outer, int p_theta, int p_phi,
                                          double B_r, double theta_max = 3.141592653589793,
                                          const Placement& placement = {});

// Cylinders of radius rc and height h standing radially on the sphere of radius rb (bases
// there, axes outward), in rings of constant theta spaced `pitch` (arc length at rb) over
// theta 0..90 deg, axially magnetized outward (sign +1) or inward (-1): the rule of the case
// files' `cylinder_array`.
std::vector<AnalyticMagnet> cylinder_array(double rc, double h, double rb, double pitch, double B_r,
                                           double sign, const Placement& placement = {});

InteractionCase segment_coupling_case(); // rotor tilted 20 deg about y
// Outer cylinders (group `on`) turned by angle_deg about y; B_r 1.305 T (cylinders) and
// 1.345 T (hemisphere), pitch 5.14 mm: 180 cylinders.
InteractionCase prototype_case(double height = 0.0125, double angle_deg = 90);
InteractionCase cylinder_pair_case();

} // namespace magfem
