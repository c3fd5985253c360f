#pragma once
// Sampling of the 3D field on line, point-list and sphere-patch probes. CSV contract (other
// tools read it):
//   line, points: x,y,z,Bx,By,Bz
//   sphere:       theta_deg,phi_deg,x,y,z,Bx,By,Bz,Brho,Btheta,Bphi
// Sphere patch: theta polar from +z, phi azimuth from +x, both about probe.center; theta_steps
// x phi_steps samples over the inclusive ranges, theta the outer loop. Brho, Btheta, Bphi are
// the components along the local spherical unit vectors. Coordinates in the case's length
// unit, B in tesla.
// B is the FE field of the tet containing the point, or, if `recovered_B` is given (one value
// per DOF, Field3D::recovered_B()), that nodal field interpolated in the tet.
#include <vector>

#include "postproc/field3d.hpp"
#include "postproc/point_locator3d.hpp"
#include "postproc/probe_spec.hpp"
#include "postproc/probe_table.hpp"

namespace magfem {

// Throws std::runtime_error naming the probe if a point lies outside the meshed domain, or
// std::invalid_argument for a 2D-only probe kind (circle).
ProbeTable sample_probe_3d(const Field3D& field, const PointLocator3D& locator,
                           const ProbeSpec& probe, double length_unit,
                           const std::vector<Eigen::Vector3d>* recovered_B = nullptr);

// The sample points of a probe in metres, in CSV row order.
std::vector<Eigen::Vector3d> probe_points_3d(const ProbeSpec& probe);

} // namespace magfem
