#pragma once
// Recovered (nodal, smooth) B of a 3D solution that never mixes materials. The element B
// jumps across a region boundary (tangentially: steel next to air by a factor mu_r), so one
// average over all tets at a shared DOF would be wrong on both sides, for probes in thin
// sheets worst of all (issue 30: 21 % low in 3.2 mm steel, 3x high 5 mm below it). Here a
// DOF keeps one value per region that touches it: the volume-weighted average of the element
// B at that DOF over that region's tets only (the shell excluded). A point of tet t is read
// from t's region values alone, so the field is continuous inside a region and a point in
// steel never sees air.
//
// Storage: one slot per (DOF, region) (region_slots.hpp). Most DOFs have one slot; only DOFs
// on region boundaries have more.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh3d.hpp"
#include "postproc/field3d.hpp"
#include "postproc/region_slots.hpp"
#include "solver/dof_map3d.hpp"

namespace magfem {

class RecoveredB3D {
public:
  RecoveredB3D() = default; // empty: n_slots() == 0, at() must not be called
  // `field` (its problem, mesh and DOF map) must outlive this object. `threads` (0 = all
  // cores): the result is the serial one bit for bit whatever the count.
  explicit RecoveredB3D(const Field3D& field, int threads = 0);

  // Recovered B (T) at bary of tet t, interpolated with the element's shape functions from
  // the values its region holds at its DOFs. t must not be a shell tet.
  Eigen::Vector3d at(std::size_t t, const std::array<double, 4>& bary) const;
  // The value region `part` (a tet_part) holds at DOF `dof`; throws std::out_of_range if
  // no tet of that region touches the DOF.
  const Eigen::Vector3d& value(int dof, int part) const;
  // How many regions hold a value at DOF `dof` (0: only the shell touches it).
  int n_regions_at(int dof) const { return slots_.regions_at(dof); }

  // One value per DOF, the volume-weighted average over all its regions: what VTU point
  // data (one value a point) can show. It mixes materials at region boundaries: for plots,
  // never for numbers. DOFs touched only by the shell get zero.
  std::vector<Eigen::Vector3d> dof_average() const;
  // Every stored value (for finiteness checks).
  const std::vector<Eigen::Vector3d>& values() const { return b_; }
  // Per tet, max |B| (T) of the element field over its DOF nodes, the values averaged here
  // (0 for shell tets): the energy summary's peak |B| (summarize_energy_3d) without
  // evaluating B at every node of every tet a second time.
  const std::vector<double>& element_peak_B() const { return element_peak_B_; }
  std::size_t n_slots() const { return b_.size(); }

private:
  const Mesh3D* mesh_ = nullptr;
  const DofMap3D* dofs_ = nullptr;
  RegionSlots slots_;                  // per (DOF, region), the shell's tets left out
  std::vector<Eigen::Vector3d> b_;     // recovered B of every slot, T
  std::vector<double> weight_;         // volume of the slot's tets around its DOF, m^3
  std::vector<double> element_peak_B_; // per tet, T
};

} // namespace magfem
