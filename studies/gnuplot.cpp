#include "studies/gnuplot.hpp"

#include <cstdlib>

namespace magfem {

bool gnuplot_available(std::string& why) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") == 0)
    return true;
  why = "gnuplot not found (apt-get install gnuplot-nox)";
  return false;
}

std::string gnuplot_title(std::string title) {
  for (char& c : title)
    if (c == '"' || c == '\\')
      c = '\'';
  return title;
}

bool run_gnuplot(const std::filesystem::path& script,
                 const std::vector<std::filesystem::path>& data_files, std::string& why) {
  const std::string cmd = "gnuplot '" + script.string() + "' > /dev/null";
  const int rc = std::system(cmd.c_str());
  std::error_code ignored; // a temporary that cannot be removed is not worth failing for
  for (const auto& p : data_files)
    std::filesystem::remove(p, ignored);
  std::filesystem::remove(script, ignored);
  if (rc != 0) {
    why = "gnuplot failed (exit " + std::to_string(rc) + ")";
    return false;
  }
  return true;
}

} // namespace magfem
