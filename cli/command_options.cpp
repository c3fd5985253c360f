#include "cli/command_options.hpp"

#include <cmath>
#include <filesystem>
#include <optional>
#include <utility>

#include "casefile/cli_number.hpp"
#include "cli/command_help.hpp"
#include "cli/materials_command.hpp"
#include "cli/mesh_command.hpp"
#include "studies/actuator.hpp"
#include "studies/optimize.hpp"
#include "studies/study.hpp"
#include "validation/validate.hpp"

namespace magfem {

namespace {

using Table = OptionTable<CommandArgs>;

void add_out(Table& t) {
  t.value("--out", "DIR", [](CommandArgs& a, auto&, const std::string& v) { a.out_dir = v; });
}

void add_mesh(Table& t) {
  t.value("--order", "1|2", [](CommandArgs& a, auto&, const std::string& v) {
    a.overrides.order = parse_cli_order(v);
  });
  // 0 would silently mean "as in the case": refused by parse_cli_mesh_scale
  t.value("--mesh-scale", "S", [](CommandArgs& a, auto&, const std::string& v) {
    a.overrides.mesh_scale = parse_cli_mesh_scale(v);
  });
  t.value("--max-memory", "GB", [](CommandArgs& a, const std::string& o, const std::string& v) {
    a.overrides.max_memory_gb = parse_cli_number(o, v);
    if (!(a.overrides.max_memory_gb > 0))
      throw_option_error(o, "must be positive (GB)");
  });
}

void add_param(Table& t) {
  t.value("--param", "NAME=VALUE", [](CommandArgs& a, auto&, const std::string& v) {
    parse_cli_parameter(v, a.parameters);
  });
}

void add_quiet(Table& t) {
  t.flag("--quiet", [](CommandArgs& a, auto&, auto&) { a.quiet = true; });
}

void add_accuracy(Table& t) {
  for (const auto& [name, placeholder] :
       {std::pair{"--accuracy", "PCT"}, std::pair{"--max-passes", "N"},
        std::pair{"--max-unknowns", "N"}})
    t.value(name, placeholder, [](CommandArgs& a, const std::string& o, const std::string& v) {
      AdaptOverrides given{a.accuracy_pct, a.max_unknowns, a.max_passes};
      parse_cli_adapt(o, v, given);
      a.accuracy_pct = given.accuracy_pct, a.max_unknowns = given.max_unknowns,
      a.max_passes = given.max_passes;
    });
}

Table solve_table() {
  Table t("solve");
  add_out(t);
  add_mesh(t);
  add_accuracy(t);
  add_param(t);
  add_quiet(t);
  return t;
}

Table analytic_table() {
  Table t("analytic");
  add_out(t);
  t.value("--model", "charge|harmonic",
          [](CommandArgs& a, auto&, const std::string& v) { a.analytic.model = v; });
  t.value("--tolerance", "T", [](CommandArgs& a, const std::string& o, const std::string& v) {
    a.analytic.tolerance = parse_cli_number(o, v);
  });
  t.value("--n-max", "N", [](CommandArgs& a, const std::string& o, const std::string& v) {
    a.analytic.n_max = static_cast<int>(parse_cli_number(o, v));
  });
  add_param(t);
  return t;
}

Table sweep_table() {
  Table t("sweep");
  auto text = [&t](const char* name, const char* placeholder, std::string CommandArgs::*field) {
    t.value(name, placeholder,
            [field](CommandArgs& a, auto&, const std::string& v) { a.*field = v; });
  };
  text("--rotate", "GROUP", &CommandArgs::rotate);
  text("--move", "GROUP", &CommandArgs::move);
  text("--axis", "x|y|z|ax,ay,az", &CommandArgs::axis);
  text("--angles", "START:STEP:END|A,B,C", &CommandArgs::angles);
  text("--positions", "START:STEP:END|A,B,C", &CommandArgs::positions);
  text("--point", "px,py,pz", &CommandArgs::point);
  t.flag("--analytic", [](CommandArgs& a, auto&, auto&) { a.analytic_sweep = true; });
  text("--surface-radius", "R", &CommandArgs::surface_radius);
  t.value("--jobs", "N", [](CommandArgs& a, const std::string& o, const std::string& v) {
    a.jobs = static_cast<int>(parse_cli_number(o, v));
    if (a.jobs < 1)
      throw_option_error(o, "must be at least 1");
  });
  add_out(t);
  add_mesh(t);
  t.flag("--resume", [](CommandArgs& a, auto&, auto&) { a.resume = true; });
  add_quiet(t);
  return t;
}

std::optional<Table> front_end_table(const std::string& command) {
  if (command == "solve")
    return solve_table();
  if (command == "analytic")
    return analytic_table();
  if (command == "sweep")
    return sweep_table();
  if (command == "compare")
    return Table("compare");
  return std::nullopt;
}

} // namespace

CommandArgs parse_command_args(int argc, char** argv) {
  if (argc < 2)
    throw InputError("<command line>", 0, "", std::string("missing command\n") + usage_overview());
  CommandArgs a;
  a.command = argv[1];
  const auto table = front_end_table(a.command);
  if (!table) {
    std::vector<OptionInfo> commands;
    for (const auto& name : command_names())
      commands.push_back({name, ""});
    const std::string guess = nearest_option(a.command, commands);
    throw InputError("<command line>", 0, "",
                     "unknown command '" + a.command + "'" +
                         (guess.empty() ? "" : " (did you mean " + guess + "?)") + "\n" +
                         usage_overview());
  }
  a.positional = table->parse(std::vector<std::string>(argv + 2, argv + argc), a);
  const std::size_t wanted = a.command == "compare" ? 2 : 1;
  if (a.positional.size() != wanted)
    throw InputError("<command line>", 0, "",
                     std::string("wrong number of arguments\n") +
                         command_usage(a.command).value_or(usage_overview()));
  a.case_file = a.positional[0];
  if (a.out_dir.empty())
    a.out_dir = (std::filesystem::path("out") / std::filesystem::path(a.case_file).stem()).string();
  return a;
}

std::vector<OptionInfo> command_options(const std::string& command) {
  if (const auto table = front_end_table(command))
    return table->options();
  if (command == "study")
    return study_option_infos();
  if (command == "optimize")
    return optimize_option_infos();
  if (command == "actuator")
    return actuator_option_infos();
  if (command == "validate")
    return validate_option_infos();
  if (command == "mesh")
    return mesh_option_infos();
  if (command == "materials")
    return materials_option_table().options();
  return {};
}

} // namespace magfem
