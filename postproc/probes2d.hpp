#pragma once
// Sampling of the 2D field on line and circle probes. CSV contract (other tools read it):
//   line:   x,y,Bx,By
//   circle: angle_deg,x,y,Bx,By,Br,Bt   (Br radial, Bt tangential = counter-clockwise)
// Axisymmetric (r-z plane, arcs about a centre in that plane, rho and theta polar about it):
//   line:   r,z,Br,Bz
//   circle: angle_deg,r,z,Br,Bz,Brho,Btheta
// Coordinates in the case's length unit, B in tesla. Values are read in the element
// containing the point: the element field itself (no recovery given), or the patch-recovered
// B* of that element's region (PatchRecovery2D: what `magfem solve` writes; 0.01-0.4x the
// element field's error, patch_recovery2d.hpp), never the nodal average of
// Field2D::recovered_B, which mixes the materials at region boundaries
// (tests/postproc/test_thin_plate2d.cpp). A point on a boundary is read in the triangle
// PointLocator2D::locate returns.
#include "postproc/field2d.hpp"
#include "postproc/patch_recovery2d.hpp"
#include "postproc/point_locator2d.hpp"
#include "postproc/probe_spec.hpp"
#include "postproc/probe_table.hpp"

namespace magfem {

// Throws std::runtime_error naming the probe if a point lies outside the meshed domain.
ProbeTable sample_probe_2d(const Field2D& field, const PointLocator2D& locator,
                           const ProbeSpec& probe, double length_unit,
                           const PatchRecovery2D* recovery = nullptr);

} // namespace magfem
