#pragma once
// Sampling of the 3D field on line, point-list, sphere-patch and plane-grid probes. CSV contract
// (other tools read it; columns are only ever added at the end):
//   line, points: x,y,z,Bx,By,Bz,region_id
//   sphere:       theta_deg,phi_deg,x,y,z,Bx,By,Bz,Brho,Btheta,Bphi,region_id
//   plane:        u,v,x,y,z,Bx,By,Bz,Bn,region_id
// Sphere patch: theta polar from +z, phi azimuth from +x, both about probe.center; theta_steps
// x phi_steps samples over the inclusive ranges, theta the outer loop. Brho, Btheta, Bphi are
// the components along the local spherical unit vectors. Plane: u, v the point's in-plane
// coordinates along plane.u and plane.v from plane.center (u the outer loop), Bn = B.n along
// plane.n. Coordinates in the case's length unit, B in tesla.
// region_id: the region the point was read in (the mesh tet_part of its
// tet: the index of the case's region, -1 for background air), as the VTU's region_id.
// B is read in the tet containing the point, from one of three fields, each of that tet's
// region alone (never averaged across materials):
//   - the element field (no recovery given): discontinuous, O(h^p) for order p;
//   - RecoveredB3D's nodal averages: continuous, the same order as the element field;
//   - PatchRecovery3D's superconvergent patch recovery (what `magfem solve` writes): one
//     order better, O(h^(p+1)) on smooth fields. On the magnetized sphere's r = 12 mm table
//     (order 2, 922k unknowns) its rms error is 0.010-0.015 % against the nodal averages'
//     0.065-0.10 %; MagnetizedSphere.ConvergenceRatesOrders1And2 asserts the orders.
// A point on a region boundary lies in tets of both sides: it is read in the one
// PointLocator3D::locate returns (the first containing tet of its bucket), and region_id says
// which; move the point off the boundary to choose.
#include <vector>

#include "postproc/field3d.hpp"
#include "postproc/patch_recovery3d.hpp"
#include "postproc/point_locator3d.hpp"
#include "postproc/probe_spec.hpp"
#include "postproc/probe_table.hpp"
#include "postproc/recovered_b3d.hpp"

namespace magfem {

// Throws std::runtime_error naming the probe if a point lies outside the meshed domain, or
// std::invalid_argument for a 2D-only probe kind (circle).
ProbeTable sample_probe_3d(const Field3D& field, const PointLocator3D& locator,
                           const ProbeSpec& probe, double length_unit,
                           const RecoveredB3D* recovered = nullptr);
// The same, B from the patch recovery (`recovery` of `field`).
ProbeTable sample_probe_3d(const Field3D& field, const PointLocator3D& locator,
                           const ProbeSpec& probe, double length_unit,
                           const PatchRecovery3D& recovery);

// The sample points of a probe in metres, in CSV row order.
std::vector<Eigen::Vector3d> probe_points_3d(const ProbeSpec& probe);
// A plane probe's in-plane coordinates (u, v) in metres, in CSV row order.
std::vector<Eigen::Vector2d> plane_probe_coordinates(const ProbeSpec& probe);

} // namespace magfem
