#pragma once
// Lorentz force and torque per metre of length on current-carrying regions of a solved 2D
// field: F = int J x B dA with J = J_z z_hat, i.e. f = J_z (-B_y, B_x), and torque about p
// T_z = int ((x - p) x f)_z dA (SI: N/m and N m/m; force in the xy-plane, torque along z).
//
// Axisymmetric (J = J_phi phi_hat over the whole turn): F = F_z z_hat with
// F_z = -int J_phi B_r 2 pi r dA (N), torque zero.
//
// B is the total FE field, including the regions' own. The exact self-field exerts no net
// force or torque on its own currents (action and reaction between their elements), so the
// result is the force exerted by everything else up to the discretization error of that
// self-term; the FE self-force is not exactly zero but converges to zero with the mesh.
// The integral uses the element B (the Galerkin solution itself, polynomial per element)
// with a rule exact for it on the straight triangles, so quadrature is not an error source.
// Only the J x B force: parts that are also magnetic (iron, magnets) feel magnetization
// forces besides, which the Maxwell stress tensor around them includes.
#include <vector>

#include <Eigen/Core>

#include "postproc/field2d.hpp"
#include "postproc/maxwell_stress.hpp"

namespace magfem {

// Sum over the given parts (Problem2D::parts indices, e.g. one coil side or a whole
// winding); parts without current contribute zero. Throws std::invalid_argument for an index
// out of range.
ForceTorque lorentz_force_2d(const Field2D& field, const std::vector<int>& parts,
                             const Eigen::Vector2d& torque_point);

} // namespace magfem
