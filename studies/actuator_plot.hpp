#pragma once
// power_map.png of `magfem actuator`: the copper loss of each demand over the orientation
// grid (gnuplot, as sweep.png), a colour map over the two angles that vary most, or a line
// over one. Each orientation is one cell of its own colour (never interpolated between
// neighbours, which would hide a peak), the worst over a third angle if that varies too;
// the worst orientation is marked and named. Ill-conditioned orientations are gaps.
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "studies/actuator.hpp"
#include "studies/actuator_coil_pitch.hpp"

namespace magfem {

// One cell of the map: the angles of its two axes (deg) and the largest copper loss over the
// orientations that share them (NaN if none could be commutated).
struct PowerMapCell {
  double x_deg = 0, y_deg = 0;
  double worst_W = std::numeric_limits<double>::quiet_NaN();
};

// The cells of demand `demand` over axes ax and ay (0 rx, 1 ry, 2 rz; ay < 0: a line over ax),
// ordered by x then y.
std::vector<PowerMapCell> power_map_cells(const ActuatorResult& result, std::size_t demand, int ax,
                                          int ay);

// Returns false with the reason in `why` if no plot was made (gnuplot missing, one
// orientation only).
bool plot_power_map(const ActuatorResult& result, const std::string& title,
                    const std::filesystem::path& png, std::string& why);

// coil_pitch.png of `magfem actuator --coil-pitch`: P_x, P_y, P_z and their mean against the
// coil pitch (as the thesis's Figs. 5.9-5.11). False with the reason in `why` if not made.
bool plot_coil_pitch(const CoilPitchStudy& study, const std::string& title,
                     const std::filesystem::path& png, std::string& why);

} // namespace magfem
