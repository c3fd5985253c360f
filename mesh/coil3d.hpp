#pragma once
// Coils in 3D as the source-field, solver and postprocessing stages see them. A coil is a
// conductor bundle of `turns` turns carrying `current` each, with the current density uniform
// over the bundle's cross-section (J = turns * current / cross-section area). Coils are not
// meshed: the reduced scalar potential carries their field through the Biot-Savart source
// field, so the mesh need not conform to them. SI metres and radians.
//
// Every primitive lives in a local frame with its axis along +z; positive current circulates
// counter-clockwise seen from +z (right-hand rule: the field inside points along +z).
#include <string>
#include <variant>

#include "mesh/placement3d.hpp"

namespace magfem {

// The thesis's coil on a sphere (Fig. 5.6a): the spherical shell r_inner <= r <= r_outer
// about the local origin (the sphere's centre), restricted to the ring of polar angles
// alpha_min <= alpha <= alpha_max about the local +z axis (the coil's own axis). In the
// thesis's notation alpha_min = G_w (coil gap radius) and alpha_max = G_w + C_w (bundle width).
struct SphericalCoil {
  double r_inner = 0, r_outer = 0;
  double alpha_min = 0, alpha_max = 0;
};

// Thick cylindrical coil: r_inner <= rho <= r_outer, -length/2 <= z <= length/2.
struct Solenoid {
  double r_inner = 0, r_outer = 0;
  double length = 0;
};

// Rectangular coil with rounded corners (TEAM benchmark coils), centred on the local origin,
// -height/2 <= z <= height/2. The inner boundary is the rounded rectangle whose straight
// sides have lengths straight_x (parallel to x) and straight_y (parallel to y), joined by
// quarter circles of radius inner_radius centred at (+-straight_x/2, +-straight_y/2); the
// bundle extends `width` outwards from it (outer corner radius inner_radius + width).
struct Racetrack {
  double straight_x = 0, straight_y = 0;
  double inner_radius = 0;
  double width = 0;
  double height = 0;
};

using CoilShape = std::variant<SphericalCoil, Solenoid, Racetrack>;

struct Coil3D {
  std::string name;
  CoilShape shape;
  Placement placement; // local -> global
  double turns = 0;
  double current = 0;          // A per turn
  double fill_factor = 0.6;    // copper area / bundle cross-section area (resistance only)
  double resistivity = 1.72e-8; // ohm m, copper at 20 C
  std::string group;           // rigid group for sweeps ("" = none)
};

} // namespace magfem
