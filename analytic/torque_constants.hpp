#pragma once
// Torque constants of stator coils in the field of a rotor (magnets and iron): for every
// rotor orientation R and coil k, Gamma_k = torque about the origin per ampere of coil k,
//   Gamma_k = integral over the coil of x x (j_k x B) dV,   j_k: current density at 1 A,
// by the coil's own volume quadrature (sources/coil_field.hpp). B is the field without coil
// currents: Gamma is the part of the torque linear in the currents (the coils' pull on the
// iron through their own field grows with i^2 and is not a torque constant).
//
// The rotor's field turns with the rotor when everything magnetic is on the rotor or is a
// sphere about the origin (rotation-invariant stator iron): then one field in the rotor's own
// frame serves every orientation, B(x) = R B_rotor(R^T x), and only the coil points move.
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "analytic/commutation.hpp"
#include "sources/coil_field.hpp"

namespace magfem {

// B (tesla) at points (metres), one result per point.
using FieldAtPoints =
    std::function<std::vector<Eigen::Vector3d>(const std::vector<Eigen::Vector3d>& points)>;

// Quadrature over a coil for its torque constant. Circular coils on a sphere: Gauss in r
// (n_r), Gauss in cos(alpha) on n_alpha_panels equal panels of n_alpha points, n_azimuth equally
// spaced azimuths about the coil axis. The field a coil 1 mm from the magnets sees varies on
// the 1 mm scale of the gap near its inner face, so the azimuth and the bundle width need
// many points. Measured on the spherical actuator design (4 orientations, charge model),
// largest error of any constant relative to the largest constant, against 12,8x4,128:
//   4, 3 x 2, 32 (default)  1.0e-3     6, 4 x 3, 48   1.1e-4     6, 8 x 3, 48   6e-5
// while CoilField::volume_quadrature(6) (6 x 6, 12 azimuths; plain Gauss across the bundle)
// is 1e-2 off and order 10 still 4e-3. Other coil shapes use CoilField::volume_quadrature(n_r).
struct CoilRule {
  int n_r = 4;
  int n_alpha = 3, n_alpha_panels = 2;
  int n_azimuth = 32;
};

std::vector<CoilQuadraturePoint> torque_quadrature(const CoilField& coil, const CoilRule& rule);

// One Gamma (3 x coils.size()) per rotation; b_rotor gives B in the rotor's own frame. All
// points of all orientations go to b_rotor in one call (so it can thread over them).
std::vector<TorqueConstants> torque_constants_rotating(const std::vector<CoilField>& coils,
                                                       const std::vector<Eigen::Matrix3d>& rotor,
                                                       const FieldAtPoints& b_rotor,
                                                       const CoilRule& rule = {});

// Gamma with B given in the global frame (a field solved with the rotor in place).
TorqueConstants torque_constants(const std::vector<CoilField>& coils, const FieldAtPoints& b,
                                 const CoilRule& rule = {});

} // namespace magfem
