#include "app/study_plot.hpp"

#include <cstdio>
#include <fstream>
#include <map>

#include "app/gnuplot.hpp"

namespace magfem {

bool plot_study(const StudyOptions& options, const std::vector<StudyDesign>& designs,
                const std::filesystem::path& png, std::string& why) {
  if (!gnuplot_available(why))
    return false;
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
