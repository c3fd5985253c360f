#pragma once
// PNG plot of a sweep (torque and force against angle) rendered by gnuplot, the Debian
// package gnuplot-nox: a plotting program is better at axes, ticks and fonts than anything
// we would hand-write, and VTK's charts need an OpenGL context a headless machine lacks.
#include <filesystem>
#include <string>
#include <vector>

#include "studies/sweep.hpp"

namespace magfem {

// Writes `png` from the rows; returns false (and says why in `why`) if gnuplot is missing or
// fails. The sweep's CSV does not depend on it.
// The x axis is the rows' position: the angle, or the offset of a translation.
bool plot_sweep(const std::vector<SweepRow>& rows, const std::string& title,
                const std::filesystem::path& png, std::string& why,
                SweepMotion motion = SweepMotion::rotate);

} // namespace magfem
