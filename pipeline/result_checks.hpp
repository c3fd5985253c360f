#pragma once
// Checks on a solved case whose answer could be silently wrong:
// - NaN or Inf anywhere in the solution, the recovered B, the energy or the forces: a
//   SolveError (exit 3, nothing written), never a summary full of "nan".
// - A B-H curve evaluated beyond its table: the curve continues with slope mu0 there (an
//   assumption, not data); a warning per region with the largest B reached.
// - A stress-tensor surface (2D circle or band, 3D sphere or box) that cuts a magnet or
//   permeable region: the tensor is only valid in air, so the force and torque on what it
//   encloses would be wrong; an InputError naming the force and the region (checked on the
//   mesh, before the forces: the stress integration itself only notices when one of its
//   quadrature points lands inside the region).
// Warnings go to summary.json under `warnings` and to the console.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "casefile/case_spec.hpp"
#include "mesh/mesh2d.hpp"
#include "mesh/mesh3d.hpp"
#include "postproc/force_spec.hpp"

namespace magfem {

struct ForceResult;

// Throws SolveError naming `what` when any value is NaN or Inf.
void check_finite(const Eigen::VectorXd& values, const std::string& what);
void check_finite(const std::vector<Eigen::Vector3d>& values, const std::string& what);
void check_finite(double value, const std::string& what);
void check_forces_finite(const std::vector<ForceResult>& forces);

// Per region (parallel to `regions`): the largest |B| reached; a warning for every
// soft-material region whose peak lies beyond the last B of its table.
std::vector<std::string> bh_extrapolation_warnings(const std::vector<RegionSpec>& regions,
                                                   const std::vector<double>& peak_B_T);
// The same from an energy summary's regions (2D or 3D: anything with peak_B_T).
template <class RegionEnergy>
std::vector<std::string> bh_extrapolation_warnings(const std::vector<RegionSpec>& regions,
                                                   const std::vector<RegionEnergy>& energies) {
  std::vector<double> peaks;
  for (const auto& r : energies)
    peaks.push_back(r.peak_B_T);
  return bh_extrapolation_warnings(regions, peaks);
}

// Throws InputError (the force's line, field forces.NAME, as the stress integration names it) when
// a stress-tensor surface cuts a magnet or permeable part: an element of the part with vertices on
// both sides of the surface, or inside a band.
void check_stress_surfaces_2d(const CaseSpec& spec, const Mesh2D& mesh);
void check_stress_surfaces_3d(const CaseSpec& spec, const Mesh3D& mesh);

} // namespace magfem
