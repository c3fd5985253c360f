#include "app/actuator_plot.hpp"

#include <fstream>
#include <map>
#include <set>
#include <utility>

#include "app/gnuplot.hpp"

namespace magfem {
namespace {

double angle(const Orientation& o, int axis) {
  return axis == 0 ? o.rx_deg : axis == 1 ? o.ry_deg : o.rz_deg;
}

} // namespace

bool plot_power_map(const ActuatorResult& r, const std::string& title,
                    const std::filesystem::path& png, std::string& why) {
  // The two axes with the most distinct angles.
  std::set<double> distinct[3];
  for (const auto& o : r.orientations)
    for (int a = 0; a < 3; ++a)
      distinct[a].insert(angle(o, a));
  int ax = 0, ay = 1;
  {
    int order[3] = {0, 1, 2};
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j)
        if (distinct[order[j]].size() > distinct[order[i]].size())
          std::swap(order[i], order[j]);
    ax = std::min(order[0], order[1]);
    ay = std::max(order[0], order[1]);
  }
  if (distinct[ax].size() < 2) {
    why = "one orientation only";
    return false;
  }
  if (!gnuplot_available(why))
    return false;
  const bool map2d = distinct[ay].size() >= 2;
  const char* names[3] = {"rx (deg)", "ry (deg)", "rz (deg)"};
  const auto script = std::filesystem::path(png).replace_extension(".gp");
  std::vector<std::filesystem::path> data;
  {
    std::ofstream g(script);
    const std::string safe_title = gnuplot_title(title);
    const std::size_t n = r.demands.size();
    g << "set terminal png size " << 520 * n + 80 << ",480 noenhanced\n"
      << "set output '" << png.string() << "'\n"
      << "set multiplot layout 1," << n << " title \"" << safe_title << "\"\n"
      << "set xlabel '" << names[ax] << "'\n";
    if (map2d)
      g << "set ylabel '" << names[ay] << "'\nset view map\nset cblabel 'P (W)'\n"
        << "set datafile missing 'nan'\n";
    else
      g << "set ylabel 'P (W)'\nset grid\n";
    for (std::size_t d = 0; d < n; ++d) {
      // Mean over the remaining axis of every (ax, ay) cell; gaps where none is usable.
      std::map<std::pair<double, double>, std::pair<double, int>> cells;
      for (std::size_t i = 0; i < r.orientations.size(); ++i) {
        const auto& o = r.orientations[i];
        auto& cell = cells[{angle(o, ax), map2d ? angle(o, ay) : 0.0}];
        const auto& c = r.demands[d].commutations[i];
        if (c.ok)
          cell.first += c.power_W, ++cell.second;
      }
      data.push_back(std::filesystem::path(png).replace_extension(".d" + std::to_string(d)));
      std::ofstream f(data.back());
      double last_x = cells.empty() ? 0 : cells.begin()->first.first;
      for (const auto& [key, v] : cells) {
        if (map2d && key.first != last_x)
          f << '\n'; // gnuplot grid rows
        last_x = key.first;
        f << key.first << ' ' << key.second << ' ';
        if (v.second > 0)
          f << v.first / v.second << '\n';
        else
          f << "nan\n";
      }
      const std::string label = r.demands[d].name;
      if (map2d)
        g << "set title '" << label << "'\nsplot '" << data.back().string()
          << "' u 1:2:3 w pm3d notitle\n";
      else
        g << "set title '" << label << "'\nplot '" << data.back().string()
          << "' u 1:3 w lp notitle\n";
    }
    g << "unset multiplot\n";
  }
  return run_gnuplot(script, data, why);
}

bool plot_coil_pitch(const CoilPitchStudy& study, const std::string& title,
                     const std::filesystem::path& png, std::string& why) {
  if (study.rows.size() < 2) {
    why = "one coil pitch only";
    return false;
  }
  if (!gnuplot_available(why))
    return false;
  const auto script = std::filesystem::path(png).replace_extension(".gp");
  const auto data = std::filesystem::path(png).replace_extension(".dat");
  {
    std::ofstream f(data);
    for (const auto& r : study.rows)
      f << r.pitch_deg << ' ' << r.P_W[0] << ' ' << r.P_W[1] << ' ' << r.P_W[2] << ' ' << r.mean_W()
        << '\n';
    std::ofstream g(script);
    g << "set terminal png size 760,520 noenhanced\n"
      << "set output '" << png.string() << "'\n"
      << "set title \"" << gnuplot_title(title) << "\"\n"
      << "set xlabel 'coil pitch (deg)'\nset ylabel 'mean copper loss at 1 N m (W)'\nset grid\n"
      << "set key top left\n"
      << "plot '" << data.string() << "' u 1:2 w lp t 'P_x', '' u 1:3 w lp t 'P_y', "
      << "'' u 1:4 w lp t 'P_z', '' u 1:5 w l lw 3 t 'mean'\n";
  }
  return run_gnuplot(script, {data}, why);
}

} // namespace magfem
