#pragma once
// Stored magnetic energy and peak flux density per region of a 3D solution, with the same
// convention as 2D (energy2d.hpp): energy density w = integral_0^B H . dB, computed from the
// H-formulation result:
//   linear media:  mu |H|^2 / 2;
//   magnets:       measured from the remanent state, mu0 mu_r |H|^2 / 2 (= |B - B_r m|^2/(2 mu));
//   soft iron:     integral_0^|B| h(b) db along the B-H curve, |B| = mu(|H|^2) |H|.
// In the open-boundary shell the metric makes the integral equal to the energy of the whole
// exterior (linear air). Values in J.
#include <string>
#include <vector>

#include "postproc/field3d.hpp"

namespace magfem {

struct RegionSummary3D {
  std::string name;
  int part = 0; // part index, or region_background_3d / region_shell_3d
  double volume_m3 = 0;
  double energy_J = 0;
  double peak_B_T = 0; // max |B| over the DOF nodes of the region's tets (0 for the shell)
  bool nonlinear = false;
  std::string from_image; // a part the model does not mesh: the part whose values stand for it
                          // by symmetry (pipeline/mirror_image_regions.hpp)
};

struct EnergySummary3D {
  double total_J = 0;
  std::vector<RegionSummary3D> regions; // parts in order, then air, then the exterior shell
};

// names: the part names, indexed like Geometry3D::parts. element_peak_B (optional): per tet,
// max |B| over its DOF nodes (RecoveredB3D::element_peak_B of the same field), taken instead
// of evaluating B there again; the summary is the same bits either way.
EnergySummary3D summarize_energy_3d(const Field3D& field, const std::vector<std::string>& names,
                                    const std::vector<double>* element_peak_B = nullptr);

} // namespace magfem
