#pragma once
// power_map.png of `magfem actuator`: the copper loss of each demand over the orientation
// grid (gnuplot, as sweep.png), a colour map over the two angles that vary most (averaged
// over a third if it varies too), or a line over one. Ill-conditioned orientations are gaps.
#include <filesystem>
#include <string>

#include "app/actuator.hpp"
#include "app/actuator_coil_pitch.hpp"

namespace magfem {

// Returns false with the reason in `why` if no plot was made (gnuplot missing, one
// orientation only).
bool plot_power_map(const ActuatorResult& result, const std::string& title,
                    const std::filesystem::path& png, std::string& why);

// coil_pitch.png of `magfem actuator --coil-pitch`: P_x, P_y, P_z and their mean against the
// coil pitch (as the thesis's Figs. 5.9-5.11). False with the reason in `why` if not made.
bool plot_coil_pitch(const CoilPitchStudy& study, const std::string& title,
                     const std::filesystem::path& png, std::string& why);

} // namespace magfem
