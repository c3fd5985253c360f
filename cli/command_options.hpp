#pragma once
// The options of the commands the front end runs itself (solve, analytic, compare, sweep),
// each command with its own table: an option another command takes is refused here, not
// silently ignored. study, optimize, actuator and validate parse theirs in their folders.
#include <optional>
#include <string>
#include <vector>

#include "casefile/case_parameter.hpp"
#include "core/option_table.hpp"
#include "pipeline/run2d.hpp"
#include "pipeline/run_analytic.hpp"

namespace magfem {

struct CommandArgs {
  std::string command;
  std::string case_file;
  std::string out_dir;
  std::vector<std::string> positional;
  RunOverrides overrides;
  AnalyticOptions analytic;
  ParameterOverrides parameters; // --param NAME=VALUE (solve, analytic)
  std::string rotate, axis, angles, point, surface_radius, move, positions;
  bool analytic_sweep = false;
  bool resume = false; // sweep: continue from the checkpoint in --out
  bool quiet = false;  // no progress lines on stderr
  int jobs = 0;
  // solve --accuracy / --max-passes / --max-unknowns: override the case file's adapt:
  std::optional<double> accuracy_pct, max_unknowns;
  std::optional<int> max_passes;
};

CommandArgs parse_command_args(int argc, char** argv);

// Every option of COMMAND (any command, also study, optimize, actuator, validate, materials)
// in the order of its table: what `magfem help COMMAND` and the bash completion must offer.
std::vector<OptionInfo> command_options(const std::string& command);

} // namespace magfem
