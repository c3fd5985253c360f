#pragma once
// Stored magnetic energy and peak flux density per region of a 2D solution.
// Energy density w = integral_0^B H . dB: for linear media nu |B|^2 / 2, for magnets measured
// from the remanent state, nu |B - B_r|^2 / 2 (= mu0 |H|^2 / 2 for mu_r = 1), for soft iron
// integrated along the B-H curve. In the open-boundary shell the metric makes the integral
// equal to the energy of the whole exterior. Planar values are per unit length (J/m),
// axisymmetric ones for the whole body of revolution (J) in the same fields.
#include <string>
#include <vector>

#include "postproc/field2d.hpp"

namespace magfem {

struct RegionSummary2D {
  std::string name;
  int part = 0; // part index, or region_background / region_shell
  double area_m2 = 0;
  double energy_J_per_m = 0;
  double peak_B_T = 0; // max |B| over the region (0 for the shell)
  bool nonlinear = false;
  std::string from_image; // a part the model does not mesh: the part whose values stand
                          // for it by symmetry (pipeline/mirror_image_regions.hpp)
};

struct EnergySummary2D {
  double total_J_per_m = 0;
  std::vector<RegionSummary2D> regions;
};

// names: the part names, indexed like Geometry2D::parts.
EnergySummary2D summarize_energy_2d(const Field2D& field, const std::vector<std::string>& names);

} // namespace magfem
