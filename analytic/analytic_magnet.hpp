#pragma once
// Input of the analytic field models (charge model, spherical harmonic model): permanent
// magnets of mu_r = 1 with a prescribed remanence pattern, and infinitely permeable spherical
// boundaries. The FE side builds the same parts from case files, so both describe one device.
#include <string>

#include <Eigen/Core>

#include "materials/magnetization.hpp"
#include "mesh/geometry3d.hpp"

namespace magfem {

// One magnet: shape in its local frame, placed by `placement` (local -> global). The
// magnetization is given in the GLOBAL frame (parallel direction and radial centre), with
// magnitude M0 = B_r / mu0 times magnetization.sign.
struct AnalyticMagnet {
  Shape3D shape;               // SphericalSegment or Cylinder (Box optional)
  Placement placement;         // local -> global
  Magnetization magnetization; // parallel direction global; radial centre global
  double B_r = 0;              // tesla
  std::string name;
};

// Infinitely permeable spherical boundary (mu_r -> infinity), modelled by imaging.
// encloses = true: the magnets lie inside the sphere (outer boundary, e.g. a back-iron
// shell); false: the magnets lie outside it (inner iron core).
struct PermeableSphere {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0; // metres
  bool encloses = true;
};

} // namespace magfem
