#include "validation/report_plot.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "studies/gnuplot.hpp"

namespace magfem {

namespace {

// Values this small are round-off of a quantity that is zero (a force that vanishes by
// symmetry comes out as 1e-13 N): drawn on their own, their noise would fill the axes and
// read as a curve. The plotted quantities are SI or percent, where 1e-9 is never a value.
constexpr double round_off_level = 1e-9;

// The range of one axis when the data alone would make gnuplot print long tick labels. A
// span of a few parts in a thousand of the values (a loss of 38.97..39.04 W) gets ticks in
// their fourth and fifth digits (38.96, 38.97, ...); a span of at least 2 units of the
// values' second digit keeps every tick at 3 significant digits, at the price of drawing such
// a curve nearly flat, which is what a 0.2 % change is. Round-off alone is drawn as zero.
// Returns "" when gnuplot's autoscale is fine.
std::string axis_range(const char* axis, const std::vector<const std::vector<double>*>& data) {
  double lo = INFINITY, hi = -INFINITY;
  for (const auto* values : data)
    for (double v : *values)
      if (std::isfinite(v))
        lo = std::min(lo, v), hi = std::max(hi, v);
  if (!(hi >= lo))
    return "";
  const double mag = std::max(std::abs(lo), std::abs(hi));
  char buf[160];
  if (mag < round_off_level) {
    std::snprintf(buf, sizeof buf,
                  "set %srange [-1:1]\nset label 1 'all values below 1e-9: zero to round-off' "
                  "at graph 0.5, 0.9 center\n",
                  axis);
    return buf;
  }
  const double min_span = 2 * std::pow(10.0, std::floor(std::log10(mag)) - 1);
  if (hi - lo >= min_span)
    return "";
  const double mid = (lo + hi) / 2;
  std::snprintf(buf, sizeof buf, "set %srange [%.17g:%.17g]\n", axis, mid - min_span / 2,
                mid + min_span / 2);
  return buf;
}

std::string datablock(const PlotSeries& s, std::size_t k) {
  std::ostringstream d;
  d.precision(17);
  d << "$d" << k << " << EOD\n";
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
    if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
      d << s.x[i] << ' ' << s.y[i] << '\n';
  return d.str() + "EOD\n";
}

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Prefixes ids and the references to them, in both quote styles gnuplot writes.
std::string prefix_ids(std::string svg, const std::string& prefix) {
  for (const std::string key : {"id='", "id=\"", "href='#", "href=\"#", "url(#"}) {
    for (auto p = svg.find(key); p != std::string::npos; p = svg.find(key, p + key.size()))
      svg.insert(p + key.size(), prefix);
  }
  return svg;
}

std::filesystem::path scratch_dir() {
  static std::atomic<int> counter{0};
  const auto dir = std::filesystem::temp_directory_path() /
                   ("magfem_plot_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  std::filesystem::create_directories(dir);
  return dir;
}

} // namespace

std::string plot_script(const Plot& plot, const std::string& svg_file) {
  static const std::array<const char*, 6> colours = {"#1f77b4", "#d62728", "#2ca02c",
                                                     "#9467bd", "#ff7f0e", "#8c564b"};
  std::vector<const std::vector<double>*> xs, ys;
  for (const auto& s : plot.series)
    xs.push_back(&s.x), ys.push_back(&s.y);
  std::ostringstream g;
  // noenhanced: labels such as T_y and B_rho are names, not subscripts.
  g << "set terminal svg size " << report_plot_width << "," << report_plot_height
    << " font 'sans-serif,12' background rgb 'white' noenhanced\n"
    << "set output '" << svg_file << "'\n"
    << "set xlabel \"" << gnuplot_title(plot.x_label) << "\"\n"
    << "set ylabel \"" << gnuplot_title(plot.y_label)
    << "\"\n"
    // %g prints a round tick as written (0.5, 20, 1e-05), never 0.50000001.
    << "set format x '%g'\nset format y '%g'\n"
    << "set grid lc rgb '#dddddd'\nset border lc rgb '#444444'\n"
    // Below the axes, inside the image: long series names cannot cover a curve or be cut.
    << "set key below left Left reverse samplen 2\n"
    // x spans the data (a margin, no extension to the next tick: theta 0..90 is not drawn
    // from -10 to 100); y gets 5 % room and ends on ticks.
    << "set autoscale xfix\nset offsets graph 0.02, graph 0.02, graph 0.05, graph 0.05\n"
    << axis_range("x", xs) << axis_range("y", ys);
  for (std::size_t k = 0; k < plot.series.size(); ++k)
    g << datablock(plot.series[k], k);
  g << "plot ";
  // Point series take different markers (open circle, cross, open square): a computed point
  // on top of a published one stays visible.
  const int markers[] = {6, 2, 4};
  int point_series = 0;
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const PlotSeries& s = plot.series[k];
    g << (k ? ", \\\n     " : "") << "$d" << k << " using 1:2 ";
    if (s.points_only)
      g << "with points pt " << markers[point_series++ % 3] << " ps 1.2 lw 2";
    else
      g << "with lines lw 2";
    g << " lc rgb '" << colours[k % colours.size()] << "' title \"" << gnuplot_title(s.name)
      << "\"";
  }
  return g.str() + "\n";
}

std::string plot_svg(const Plot& plot, const std::string& id_prefix, std::string& why) {
  if (plot.series.empty()) {
    why = "no data";
    return "";
  }
  const auto dir = scratch_dir();
  const auto svg_file = dir / "plot.svg";
  const auto script = dir / "plot.gp";
  std::ofstream(script) << plot_script(plot, svg_file.string());
  std::string svg;
  if (run_gnuplot(script, {}, why))
    svg = read_file(svg_file);
  std::error_code ignored; // a scratch folder left behind is not worth failing the report for
  std::filesystem::remove_all(dir, ignored);
  const auto start = svg.find("<svg");
  if (start == std::string::npos) {
    if (why.empty())
      why = "gnuplot wrote no SVG";
    return "";
  }
  return prefix_ids(svg.substr(start), id_prefix);
}

} // namespace magfem
