// magfem command-line front end. Exit codes: 0 success, 1 internal error, 2 bad input
// (case file, options), 3 the solver did not converge.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "app/run2d.hpp"
#include "core/input_error.hpp"

namespace {

constexpr const char* usage =
    "usage: magfem solve CASE.yaml [--out DIR] [--order 1|2] [--mesh-scale S]\n"
    "\n"
    "  solve    mesh and solve a case, write summary.json, one CSV per probe and\n"
    "           solution.vtu into DIR (default: out/<case name>)\n";

struct Args {
  std::string command;
  std::string case_file;
  std::string out_dir;
  magfem::RunOverrides overrides;
};

double parse_number(const std::string& option, const char* text) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == std::strlen(text)) return v;
  } catch (const std::exception&) {
  }
  throw magfem::InputError("<command line>", 0, option, std::string("expected a number, got '") + text + "'");
}

Args parse_args(int argc, char** argv) {
  if (argc < 2) throw magfem::InputError("<command line>", 0, "", std::string("missing command\n") + usage);
  Args a;
  a.command = argv[1];
  std::vector<std::string> positional;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) throw magfem::InputError("<command line>", 0, arg, "missing value");
      return argv[++i];
    };
    if (arg == "--out") a.out_dir = value();
    else if (arg == "--order") a.overrides.order = static_cast<int>(parse_number(arg, value()));
    else if (arg == "--mesh-scale") a.overrides.mesh_scale = parse_number(arg, value());
    else if (arg.rfind("--", 0) == 0) throw magfem::InputError("<command line>", 0, arg, "unknown option");
    else positional.push_back(arg);
  }
  if (positional.size() != 1)
    throw magfem::InputError("<command line>", 0, "", std::string("expected one case file\n") + usage);
  a.case_file = positional[0];
  if (a.out_dir.empty())
    a.out_dir = (std::filesystem::path("out") / std::filesystem::path(a.case_file).stem()).string();
  if (a.overrides.order != 0 && a.overrides.order != 1 && a.overrides.order != 2)
    throw magfem::InputError("<command line>", 0, "--order", "must be 1 or 2");
  return a;
}

int run_solve(const Args& args) {
  auto spec = magfem::read_case(args.case_file);
  auto run = magfem::run_case_2d(std::move(spec), args.overrides);
  std::cout << magfem::describe_run_2d(*run);
  magfem::write_outputs_2d(*run, args.out_dir);
  std::cout << "wrote    " << args.out_dir << "/summary.json";
  for (const auto& p : run->probes) std::cout << ", " << p.name << ".csv";
  if (run->spec.write_vtu) std::cout << ", solution.vtu";
  std::cout << "\n";
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  try {
    if (argc >= 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
      std::cout << usage;
      return 0;
    }
    const Args args = parse_args(argc, argv);
    if (args.command == "solve") return run_solve(args);
    throw magfem::InputError("<command line>", 0, "", "unknown command '" + args.command + "'\n" + usage);
  } catch (const magfem::InputError& e) {
    std::cerr << "magfem: error: " << e.what() << "\n";
    return 2;
  } catch (const magfem::SolveError& e) {
    std::cerr << "magfem: solver failed: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "magfem: internal error: " << e.what() << "\n";
    return 1;
  }
}
