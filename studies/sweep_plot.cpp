#include "studies/sweep_plot.hpp"

#include <fstream>

#include "studies/gnuplot.hpp"

namespace magfem {

bool plot_sweep(const std::vector<SweepRow>& rows, const std::string& title,
                const std::filesystem::path& png, std::string& why, SweepMotion motion,
                const SweepPlotLabels& labels) {
  if (!gnuplot_available(why))
    return false;
  const auto data = std::filesystem::path(png).replace_extension(".dat");
  const auto script = std::filesystem::path(png).replace_extension(".gp");
  {
    std::ofstream d(data);
    for (const auto& r : rows)
      if (r.ok)
        d << r.angle_deg << ' ' << r.torque.x() << ' ' << r.torque.y() << ' ' << r.torque.z() << ' '
          << r.force.x() << ' ' << r.force.y() << ' ' << r.force.z() << '\n';
    std::ofstream g(script);
    g << "set terminal png size 1200,500 noenhanced\n"
      << "set output '" << png.string() << "'\n"
      << "set multiplot layout 1,2 title \"" << gnuplot_title(title) << "\"\n"
      << "set grid\nset xlabel '"
      << (motion == SweepMotion::rotate ? "angle (deg)" : "offset along the axis (mm)") << "'\n"
      << "set ylabel '" << labels.torque << "'\n"
      << "plot '" << data.string()
      << "' u 1:2 w lp t 'Tx', '' u 1:3 w lp t 'Ty', '' u 1:4 w lp t 'Tz'\n"
      << "set ylabel '" << labels.force << "'\n"
      << "plot '" << data.string()
      << "' u 1:5 w lp t 'Fx', '' u 1:6 w lp t 'Fy', '' u 1:7 w lp t 'Fz'\n"
      << "unset multiplot\n";
  }
  return run_gnuplot(script, {data}, why);
}

} // namespace magfem
