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
// The x axis is the rows' position: the angle, or the offset of a translation; the y axes are
// labelled as the rows are meant (3D: about the origin, N m and N; planar: about the sweep's
// point, per metre).
struct SweepPlotLabels {
  std::string torque = "torque about the origin (N m)";
  std::string force = "force on the group (N)";
};
bool plot_sweep(const std::vector<SweepRow>& rows, const std::string& title,
                const std::filesystem::path& png, std::string& why,
                SweepMotion motion = SweepMotion::rotate, const SweepPlotLabels& labels = {});

} // namespace magfem
