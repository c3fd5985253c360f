#pragma once
// power_map.png of `magfem actuator`: the copper loss of each demand over the orientation
// grid (gnuplot, as sweep.png), a colour map over the two angles that vary most (averaged
// over a third if it varies too), or a line over one. Ill-conditioned orientations are gaps.
#include <filesystem>
#include <string>

#include "app/actuator.hpp"

namespace magfem {

// Returns false with the reason in `why` if no plot was made (gnuplot missing, one
// orientation only).
bool plot_power_map(const ActuatorResult& result, const std::string& title,
                    const std::filesystem::path& png, std::string& why);

} // namespace magfem
