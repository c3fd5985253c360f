#pragma once
// A 3D probe's CSV table from field values already computed at probe_points_3d(probe), for
// field sources other than the FE solution (the analytic models). The columns of
// sample_probe_3d without its last, region_id (no mesh): line/points x,y,z,Bx,By,Bz; sphere
// theta_deg,phi_deg,x,y,z,Bx,By,Bz,Brho,Btheta,Bphi; plane u,v,x,y,z,Bx,By,Bz,Bn.
#include <vector>

#include <Eigen/Core>

#include "postproc/probe_spec.hpp"
#include "postproc/probe_table.hpp"

namespace magfem {

ProbeTable tabulate_probe_3d(const ProbeSpec& probe, const std::vector<Eigen::Vector3d>& points,
                             const std::vector<Eigen::Vector3d>& B, double length_unit);

} // namespace magfem
