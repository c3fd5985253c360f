#pragma once
// A planar or axisymmetric case cut at symmetry planes (mesh/symmetry_plane2d.hpp): what the
// 2D pipeline does besides meshing the share, so that every output is the whole device's.
//   - energies (total, per region, the error estimate's eta^2): 2 per plane in all, per part
//     2 per plane that cuts it (a part on one side is whole in the model; its image beyond is
//     another part, not meshed);
//   - current densities from ampere-turns: over the whole coil's area, not its share;
//   - axisymmetric coils: one the plane cuts has as linkage N times the mean of 2 pi r A over
//     the coil, the same over the share as over the whole coil (A is even about a `normal`
//     plane), and so is the inductance: nothing to scale; a coil whose image is another coil
//     takes its linkage from its image's and the pair's inductances from a second solve
//     (coil_results_axi.hpp);
//   - probes, stress circles, bands and contours sample the whole device through the mirror
//     (PointLocator2D); line sections are cut at the planes and their pieces beyond read at
//     their images; Lorentz forces sum the images of every meshed part: the force component
//     normal to a plane cancels on a part the plane cuts, the one along it doubles (planar
//     F_x on a part cut by x = 0 is zero and F_y twice the share's; axisymmetric F_z on a
//     coil cut by z = 0 is zero), the torque about a point on the plane cancels.
#include <vector>

#include <nlohmann/json.hpp>

#include "casefile/case_spec.hpp"
#include "mesh/mesh2d.hpp"
#include "postproc/field2d.hpp"
#include "postproc/maxwell_stress.hpp"
#include "postproc/section_flux2d.hpp"

namespace magfem {

struct Run2D;

// m^2 per part: the meshed area times the part's symmetry factor (the whole part's area; a
// part beyond a plane, not meshed, has its image's).
std::vector<double> whole_part_areas(const CaseSpec& spec, const Mesh2D& mesh);

// The model's energies and error estimate -> the whole device's. No-op without planes.
void scale_to_whole_device_2d(Run2D& run);

// integrate_section_2d over the whole line: its pieces beyond the planes read at their images.
SectionFlux integrate_section_whole_2d(const Field2D& field, const SectionSpec& section,
                                       double depth, const CaseSpec& spec);

// lorentz_force_2d on the whole device's parts (planes or not), torque about torque_point.
ForceTorque lorentz_force_whole_2d(const Field2D& field, const std::vector<int>& parts,
                                   const Eigen::Vector2d& torque_point, const CaseSpec& spec);

// summary.json's "symmetry" and "symmetry_factor" (nothing without planes).
void add_symmetry_json_2d(nlohmann::ordered_json& j, const CaseSpec& spec);

} // namespace magfem
