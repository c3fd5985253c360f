#pragma once
// The plots of report.html, drawn by gnuplot's SVG terminal: gnuplot picks round ticks and
// lays the legend out below the axes inside the image, which the hand-written SVG did not
// (its legends ran off a 640 px frame and its ticks were the range cut in four). gnuplot is
// an optional dependency: without it the page says why a plot is missing and the run goes on.
#include <string>

#include "validation/validate_evaluators.hpp"

namespace magfem {

// Pixel size of every plot (CSS scales it down on narrow windows).
inline constexpr int report_plot_width = 600, report_plot_height = 380;

// The plot as an <svg> element ready to inline in HTML: no XML prolog, and every id (and
// reference to one) prefixed with `id_prefix`, because gnuplot names its markers the same in
// every file and the page holds many plots. Empty, with `why`, when gnuplot fails.
std::string plot_svg(const Plot& plot, const std::string& id_prefix, std::string& why);

// The gnuplot script that draws `plot` into `svg_file` (data inline; exposed for tests).
std::string plot_script(const Plot& plot, const std::string& svg_file);

} // namespace magfem
