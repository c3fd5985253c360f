#include "studies/study_plot.hpp"

#include <cstdio>
#include <fstream>
#include <map>

#include "studies/gnuplot.hpp"

namespace magfem {
namespace {

bool is_map(const StudyOptions& options) {
  return options.parameters.size() == 2 && options.parameters[0].values.size() >= 2 &&
         options.parameters[1].values.size() >= 2;
}

// The grid's order (first parameter slowest) gives one gnuplot scan per value of the first
// parameter; a failed design is a hole ('nan') rather than a distorted surface.
bool plot_study_map(const StudyOptions& options, const std::vector<StudyDesign>& designs,
                    const std::filesystem::path& png, std::string& why) {
  const auto data = std::filesystem::path(png).replace_extension(".dat");
  const auto script = std::filesystem::path(png).replace_extension(".gp");
  const auto n_obj = options.objectives.size();
  bool any = false;
  for (const auto& d : designs)
    any |= d.ok;
  if (!any) {
    why = "no design succeeded";
    return false;
  }
  {
    std::ofstream out(data);
    out.precision(10);
    for (std::size_t i = 0; i < designs.size(); ++i) {
      const auto& d = designs[i];
      if (i > 0 && d.parameters[0] != designs[i - 1].parameters[0])
        out << '\n';
      out << d.parameters[0] << ' ' << d.parameters[1];
      for (std::size_t k = 0; k < n_obj; ++k)
        d.ok ? out << ' ' << d.objectives[k] : out << " nan";
      out << '\n';
    }
    std::ofstream g(script);
    g << "set terminal png size " << 620 * n_obj << ",520 noenhanced\n"
      << "set output '" << png.string() << "'\n"
      << "set multiplot layout 1," << n_obj << " title \"" << gnuplot_title(options.case_file)
      << "\"\n"
      << "set datafile missing 'nan'\nset view map\nset contour base\nset cntrparam levels 10\n"
      << "set style textbox opaque noborder\nset xlabel '" << options.parameters[0].name
      << "'\nset ylabel '" << options.parameters[1].name << "'\n";
    for (std::size_t k = 0; k < n_obj; ++k)
      g << "set title '" << options.objectives[k].name << "'\nsplot '" << data.string()
        << "' u 1:2:" << k + 3 << " w pm3d notitle, '' u 1:2:" << k + 3
        << " w lines nosurface lc 'black' notitle\n";
    g << "unset multiplot\n";
  }
  return run_gnuplot(script, {data}, why);
}

} // namespace

bool plot_study(const StudyOptions& options, const std::vector<StudyDesign>& designs,
                const std::filesystem::path& png, std::string& why) {
  if (!gnuplot_available(why))
    return false;
  if (is_map(options))
    return plot_study_map(options, designs, png, why);
  // One gnuplot data block per combination of the other parameters (the grid's order keeps
  // the first parameter's values apart, so group explicitly).
  std::map<std::vector<double>, std::vector<const StudyDesign*>> lines;
  for (const auto& d : designs)
    if (d.ok)
      lines[std::vector<double>(d.parameters.begin() + 1, d.parameters.end())].push_back(&d);
  if (lines.empty()) {
    why = "no design succeeded";
    return false;
  }
  const auto data = std::filesystem::path(png).replace_extension(".dat");
  const auto script = std::filesystem::path(png).replace_extension(".gp");
  {
    std::ofstream out(data);
    for (const auto& [others, points] : lines) {
      for (const auto* d : points) {
        out << d->parameters.front();
        for (double v : d->objectives)
          out << ' ' << v;
        out << '\n';
      }
      out << "\n\n";
    }
    std::ofstream g(script);
    const std::string title = gnuplot_title(options.case_file);
    const auto n_obj = options.objectives.size();
    g << "set terminal png size " << 600 * n_obj << ",500 noenhanced\n"
      << "set output '" << png.string() << "'\n"
      << "set multiplot layout 1," << n_obj << " title \"" << title << "\"\n"
      << "set grid\nset xlabel '" << options.parameters.front().name << "'\n";
    for (std::size_t k = 0; k < n_obj; ++k) {
      g << "set ylabel '" << options.objectives[k].name << "'\nplot ";
      std::size_t block = 0;
      for (const auto& [others, points] : lines) {
        std::string label;
        for (std::size_t i = 0; i < others.size(); ++i) {
          char value[32];
          std::snprintf(value, sizeof value, " %g", others[i]);
          label += (i ? ", " : "") + options.parameters[i + 1].name + value;
        }
        g << (block ? ", " : "") << "'" << data.string() << "' index " << block << " u 1:" << k + 2
          << " w lp t '" << (label.empty() ? options.objectives[k].name : label) << "'";
        ++block;
      }
      g << "\n";
    }
    g << "unset multiplot\n";
  }
  return run_gnuplot(script, {data}, why);
}

} // namespace magfem
