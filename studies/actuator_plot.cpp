#include "studies/actuator_plot.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <utility>

#include "studies/gnuplot.hpp"

namespace magfem {
namespace {

double angle(const Orientation& o, int axis) {
  return axis == 0 ? o.rx_deg : axis == 1 ? o.ry_deg : o.rz_deg;
}

} // namespace

std::vector<PowerMapCell> power_map_cells(const ActuatorResult& r, std::size_t demand, int ax,
                                          int ay) {
  std::map<std::pair<double, double>, PowerMapCell> cells;
  for (std::size_t i = 0; i < r.orientations.size(); ++i) {
    const auto& o = r.orientations[i];
    const std::pair<double, double> key{angle(o, ax), ay >= 0 ? angle(o, ay) : 0.0};
    auto& cell = cells[key];
    cell.x_deg = key.first;
    cell.y_deg = key.second;
    const auto& c = r.demands[demand].commutations[i];
    if (c.ok && !(c.power_W <= cell.worst_W)) // NaN (none yet) or larger
      cell.worst_W = c.power_W;
  }
  std::vector<PowerMapCell> out;
  for (const auto& [key, cell] : cells)
    out.push_back(cell);
  return out;
}

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
  const int third = 3 - ax - ay;
  const bool third_varies = map2d && distinct[third].size() >= 2;
  const char* names[3] = {"rx (deg)", "ry (deg)", "rz (deg)"};
  const char* short_names[3] = {"rx", "ry", "rz"};
  const auto script = std::filesystem::path(png).replace_extension(".gp");
  std::vector<std::filesystem::path> data;
  {
    std::ofstream g(script);
    const std::string safe_title = gnuplot_title(title);
    const std::size_t n = r.demands.size();
    g << "set terminal png size " << 560 * n + 80 << ",500 noenhanced\n"
      << "set output '" << png.string() << "'\n"
      << "set multiplot layout 1," << n << " title \"" << safe_title << "\"\n"
      << "set xlabel '" << names[ax] << "'\nset datafile missing 'nan'\n";
    if (map2d)
      g << "set ylabel '" << names[ay] << "'\nset cblabel 'P (W)"
        << (third_varies ? std::string(", worst over ") + short_names[third] : std::string())
        << "'\nset key below\nset size ratio -1\n";
    else
      g << "set ylabel 'P (W)'\nset grid\nset key below\n";
    for (std::size_t d = 0; d < n; ++d) {
      const auto cells = power_map_cells(r, d, ax, map2d ? ay : -1);
      data.push_back(std::filesystem::path(png).replace_extension(".d" + std::to_string(d)));
      const PowerMapCell* worst = nullptr;
      {
        std::ofstream f(data.back());
        f.precision(10);
        double last_x = cells.empty() ? 0 : cells.front().x_deg;
        for (const auto& c : cells) {
          if (map2d && c.x_deg != last_x)
            f << '\n'; // gnuplot grid rows
          last_x = c.x_deg;
          f << c.x_deg << ' ' << c.y_deg << ' ';
          if (std::isnan(c.worst_W))
            f << "nan\n";
          else
            f << c.worst_W << '\n';
          if (!std::isnan(c.worst_W) && (!worst || c.worst_W > worst->worst_W))
            worst = &c;
        }
      }
      const std::string label = r.demands[d].name;
      g << "set title '" << label << "'\n";
      std::ostringstream mark;
      if (worst) {
        mark << ", '-' u 1:2 w p pt 6 ps 3 lw 2 lc 'black' t 'worst: " << std::setprecision(4)
             << worst->worst_W << " W at " << short_names[ax] << " " << worst->x_deg;
        if (map2d)
          mark << ", " << short_names[ay] << " " << worst->y_deg;
        mark << "'";
      }
      // `with image`: one rectangle per orientation in its own colour (pm3d would colour each
      // tile with the mean of its four corners and hide the peak).
      if (map2d)
        g << "plot '" << data.back().string() << "' u 1:2:3 w image notitle" << mark.str() << "\n";
      else
        g << "plot '" << data.back().string() << "' u 1:3 w lp notitle" << mark.str() << "\n";
      if (worst)
        g << worst->x_deg << ' ' << (map2d ? worst->y_deg : worst->worst_W) << "\ne\n";
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
