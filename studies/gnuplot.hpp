#pragma once
// The PNG plots of sweep, study and actuator are drawn by gnuplot (an optional runtime
// dependency): a missing or failing gnuplot costs the plot, never the run, so every call
// reports why it did not plot instead of throwing.
#include <filesystem>
#include <string>
#include <vector>

namespace magfem {

// False (and why) when no gnuplot is on the PATH.
bool gnuplot_available(std::string& why);

// A title safe inside gnuplot's double quotes (quotes and backslashes become ').
std::string gnuplot_title(std::string title);

// Runs gnuplot on the script, then removes the script and its data files whatever happened;
// gnuplot's own messages go to stderr.
bool run_gnuplot(const std::filesystem::path& script,
                 const std::vector<std::filesystem::path>& data_files, std::string& why);

} // namespace magfem
