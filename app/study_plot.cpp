#include "app/study_plot.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>

namespace magfem {

bool plot_study(const StudyOptions& options, const std::vector<StudyDesign>& designs,
                const std::filesystem::path& png, std::string& why) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
    why = "gnuplot not found (apt-get install gnuplot-nox)";
    return false;
  }
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
    std::string title = options.case_file;
    for (char& c : title)
      if (c == '"' || c == '\\')
        c = '\'';
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
  const std::string cmd = "gnuplot '" + script.string() + "' 2>&1";
  const int rc = std::system(cmd.c_str());
  std::filesystem::remove(data);
  std::filesystem::remove(script);
  if (rc != 0) {
    why = "gnuplot failed (exit " + std::to_string(rc) + ")";
    return false;
  }
  return true;
}

} // namespace magfem
