// magfem command-line front end. Exit codes: 0 success, 1 internal error, 2 bad input
// (case file, options), 3 the solver did not converge.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "casefile/case_spec.hpp"
#include "casefile/cli_number.hpp"
#include "cli/command_help.hpp"
#include "cli/command_options.hpp"
#include "cli/materials_command.hpp"
#include "cli/mesh_command.hpp"
#include "core/backend_module.hpp"
#include "core/input_error.hpp"
#include "core/interrupt.hpp"
#include "core/output_stage.hpp"
#include "core/thread_count.hpp"
#include "pipeline/build_info.hpp"
#include "pipeline/resource_usage.hpp"
#include "pipeline/run2d.hpp"
#include "pipeline/run3d.hpp"
#include "pipeline/run_analytic.hpp"
#include "pipeline/run_checkpoint.hpp"
#include "pipeline/solve_case.hpp"
#include "postproc/probe_compare.hpp"
#include "solver/mpi_context.hpp"
#include "studies/actuator.hpp"
#include "studies/optimize.hpp"
#include "studies/study.hpp"
#include "studies/sweep.hpp"
#include "studies/sweep_axi.hpp"
#include "studies/sweep_planar.hpp"
#include "studies/sweep_plot.hpp"
#include "validation/validate.hpp"

namespace {

using Args = magfem::CommandArgs;

// "wrote    DIR/summary.json, a.csv, ...": every file the run wrote.
void print_written(const std::string& out_dir, const std::vector<std::string>& files) {
  std::cout << "wrote    " << out_dir << "/";
  for (std::size_t i = 0; i < files.size(); ++i)
    std::cout << (i ? ", " : "") << files[i];
  std::cout << "\n";
}

// One console line per adaptive pass, as it ends.
std::function<void(const magfem::AdaptPass&)> print_pass(const char* element_word) {
  return [element_word](const magfem::AdaptPass& p) {
    std::cout << magfem::describe_adapt_pass(p, element_word) << std::flush;
  };
}

int run_solve_3d(const Args& args, magfem::CaseSpec spec, magfem::RunOverrides overrides) {
  auto run = magfem::solve_case_3d(std::move(spec), overrides, print_pass("tetrahedra"));
  if (!overrides.world.is_root()) { // rank 0 reports and writes, once
    magfem::idle_barrier();
    return 0;
  }
  std::cout << magfem::describe_run_3d(*run);
  print_written(args.out_dir, magfem::write_outputs_3d(*run, args.out_dir));
  std::cout.flush();
  magfem::idle_barrier();
  return 0;
}

// The command line's --accuracy / --max-passes / --max-unknowns over the case file's adapt:.
void apply_adapt_options(const Args& args, magfem::CaseSpec& spec) {
  magfem::apply_adapt_overrides(spec.adapt, {args.accuracy_pct, args.max_unknowns, args.max_passes},
                                {"<command line>", "--accuracy", "--max-passes", "--max-unknowns"});
}

int run_solve(const Args& args) {
  // Under mpirun: MPI starts here, before anything can fail on one process only.
  const magfem::MpiWorld world = magfem::join_mpi_world();
  auto spec = magfem::read_case(args.case_file, args.parameters);
  apply_adapt_options(args, spec);
  magfem::Progress progress;
  magfem::RunOverrides overrides = args.overrides;
  if (!args.quiet && world.is_root())
    overrides.progress = &progress;
  if (world.distributed()) {
    if (spec.dimension != 3)
      throw magfem::InputError(spec.file, 0, "dimension",
                               "2D and axisymmetric cases are solved on one process (CHOLMOD); "
                               "run this case without mpirun");
    overrides.world = world;
    // The memory guard: every process holds the whole mesh, and those on one machine share
    // its memory.
    overrides.parallel_runs = world.size_on_node;
  }
  if (spec.dimension == 3)
    return run_solve_3d(args, std::move(spec), overrides);
  auto run = magfem::solve_case_2d(std::move(spec), overrides, print_pass("triangles"));
  std::cout << magfem::describe_run_2d(*run);
  print_written(args.out_dir, magfem::write_outputs_2d(*run, args.out_dir));
  return 0;
}

int run_analytic(const Args& args) {
  auto run =
      magfem::run_case_analytic(magfem::read_case(args.case_file, args.parameters), args.analytic);
  std::cout << magfem::describe_analytic(*run);
  print_written(args.out_dir, magfem::write_outputs_analytic(*run, args.out_dir));
  return 0;
}

void show_progress(int done, int total) {
  if (isatty(STDERR_FILENO)) {
    constexpr int width = 30;
    const int filled = width * done / total;
    std::fprintf(stderr, "\r[%s%s] %d/%d positions", std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(), done, total);
    if (done == total)
      std::fputc('\n', stderr);
  } else {
    std::fprintf(stderr, "position %d/%d done\n", done, total);
  }
}

void report_restored(const magfem::RunCheckpoint& checkpoint) {
  if (checkpoint.n_restored())
    std::fprintf(stderr, "magfem: --resume: %zu finished positions from the checkpoint\n",
                 checkpoint.n_restored());
}

// The summed time of a sweep's positions (restored ones with their original time).
template <class Row> double position_time(const std::vector<Row>& rows) {
  double total_s = 0;
  for (const auto& r : rows)
    total_s += r.seconds;
  return total_s;
}

// Under mpirun a sweep's positions, a study's designs and validate's entries are dealt to the
// processes (studies/position_runner.hpp). Each process takes its share of its machine's
// cores: that many items at once unless --jobs says otherwise, and that many threads in each
// solve's element loops unless MAGFEM_THREADS says otherwise (set here, before any of this
// process's threads reads it). Said once, by rank 0. `at_once`: what a process does at
// once, with N for the number (--jobs, else the process's cores).
magfem::MpiWorld dealt_world(const std::string& command, const std::string& items, int jobs,
                             std::string at_once) {
  const magfem::MpiWorld world = magfem::join_mpi_world(true); // started by start_mpi_or_refuse
  if (!world.distributed())
    return world;
  const int threads = magfem::threads_per_process(world);
  setenv("MAGFEM_THREADS", std::to_string(threads).c_str(), 0);
  if (const auto n = at_once.find('N'); n != std::string::npos)
    at_once.replace(n, 1, std::to_string(jobs > 0 ? jobs : threads)) +=
        jobs > 0 ? " (--jobs)" : " (its share of the machine's cores)";
  if (world.is_root())
    std::fprintf(stderr,
                 "magfem: %s on %d processes (%d on this machine), %s dealt one at a time: each "
                 "process %s with %d element-loop threads (MAGFEM_THREADS)%s\n",
                 command.c_str(), world.size, world.size_on_node, items.c_str(), at_once.c_str(),
                 magfem::available_threads(),
                 world.any_thread_calls_mpi
                     ? ""
                     : "; MPI gave no MPI_THREAD_MULTIPLE: rank 0 only deals, and the others "
                       "solve one at a time");
  return world;
}

magfem::MpiWorld sweep_world(const Args& args) {
  return dealt_world("sweep", "positions", args.jobs, "solves N at once");
}

// The checkpoint of a sweep: rank 0's alone under mpirun (the other processes send it their
// rows), so that a resumed run, with or without mpirun, finds every finished position.
std::unique_ptr<magfem::RunCheckpoint>
sweep_checkpoint(const magfem::MpiWorld& world, const Args& args, const std::string& identity) {
  if (!world.is_root())
    return nullptr;
  auto checkpoint = std::make_unique<magfem::RunCheckpoint>(args.out_dir, identity, args.resume);
  report_restored(*checkpoint);
  return checkpoint;
}

// Axial sweep of an axisymmetric case (studies/sweep_axi.hpp).
int run_sweep_axi(const Args& args) {
  using magfem::InputError;
  const std::string cli = "<command line>";
  const auto spec = magfem::read_case(args.case_file);
  if (args.axis != "z")
    throw InputError(cli, 0, "--axis", "an axisymmetric group moves along z: give --axis z");
  if (args.positions.empty())
    throw InputError(cli, 0, "--positions", "give the positions (mm)");
  magfem::AxiSweepOptions o;
  o.group = args.move;
  for (const double p : magfem::parse_angle_list(args.positions, "--positions"))
    o.positions_m.push_back(1e-3 * p);
  o.jobs = args.jobs;
  o.order = args.overrides.order;
  o.mesh_scale = args.overrides.mesh_scale;
  o.max_memory_gb = args.overrides.max_memory_gb;
  o.world = sweep_world(args);
  const auto checkpoint =
      sweep_checkpoint(o.world, args,
                       magfem::checkpoint_identity("sweep --move", args.case_file,
                                                   magfem::sweep_axi_checkpoint_options(o)));
  o.checkpoint = checkpoint.get();
  const bool quiet = args.quiet || !o.world.is_root();
  const auto rows =
      magfem::run_sweep_axi(spec, o, quiet ? magfem::AxiSweepProgress{} : show_progress);
  if (!o.world.is_root()) // rank 0 has the rows, and writes and reports them
    return magfem::code_of_root(0);

  magfem::OutputStage stage(args.out_dir);
  stage.write_text("sweep.csv", magfem::sweep_axi_csv(rows));
  nlohmann::ordered_json j = magfem::sweep_axi_summary(spec, rows, o);
  j["peak_memory_MB"] = magfem::peak_memory_mb();
  const int failed = j["failed_positions"].get<int>();
  const double total_s = position_time(rows);
  stage.write_text("summary.json", j.dump(2) + "\n");
  stage.commit();
  checkpoint->remove();
  std::printf("%12s %14s %9s\n", "position_mm", "Fz_N", "time_s");
  for (const auto& r : rows)
    if (r.ok)
      std::printf("%12.4f %14.6g %9.2f\n", 1e3 * r.position_m, r.fz_N, r.seconds);
    else
      std::printf("%12.4f FAILED: %s\n", 1e3 * r.position_m, r.error.c_str());
  for (const auto& w : magfem::sweep_axi_warnings(rows))
    std::printf("warning  %s\n", w.c_str());
  std::printf("wrote    %s/sweep.csv, summary.json (%.1f s of position time)\n",
              args.out_dir.c_str(), total_s);
  std::fflush(stdout);
  if (failed)
    std::cerr << "magfem: " << failed << " of " << rows.size() << " positions failed\n";
  return magfem::code_of_root(failed ? 3 : 0);
}

int run_sweep(const Args& args) {
  using magfem::InputError;
  const std::string cli = "<command line>";
  if (!args.move.empty() && !args.rotate.empty())
    throw InputError(cli, 0, "--move", "give --rotate GROUP or --move GROUP, not both");
  const bool translate = !args.move.empty();
  const auto spec = magfem::read_case(args.case_file);
  const bool axisymmetric = spec.axisymmetric();
  // --point is the point a rotation turns about, or the one a translation's torque is about
  // (carried with the group): an axisymmetric translation has no torque, and an ignored
  // option would look as if it had worked.
  if (translate && !args.point.empty() && axisymmetric)
    throw InputError(cli, 0, "--point",
                     "an axisymmetric --move sweep has no torque, so no point; --point goes "
                     "with --rotate, or a 3D or planar --move");
  if (translate && axisymmetric)
    return run_sweep_axi(args);
  if (!translate && args.rotate.empty())
    throw InputError(cli, 0, "--rotate", "name the group to rotate (or --move GROUP)");
  if (args.axis.empty())
    throw InputError(cli, 0, "--axis", translate ? "give the direction" : "give the rotation axis");
  if (translate && !args.angles.empty())
    throw InputError(cli, 0, "--angles", "--move takes --positions (mm)");
  if (translate && args.positions.empty())
    throw InputError(cli, 0, "--positions", "give the positions (mm)");
  if (!translate && args.angles.empty())
    throw InputError(cli, 0, "--angles", "give the angles");
  const double s = spec.length_unit;
  const bool planar = spec.dimension == 2 && !spec.axisymmetric();
  magfem::SweepOptions o;
  o.group = translate ? args.move : args.rotate;
  o.motion = translate ? magfem::SweepMotion::translate : magfem::SweepMotion::rotate;
  o.axis = magfem::parse_axis(args.axis, planar);
  if (translate)
    for (const double p : magfem::parse_angle_list(args.positions, "--positions"))
      o.offsets_m.push_back(1e-3 * p);
  else
    o.angles_deg = magfem::parse_angle_list(args.angles);
  if (!args.point.empty())
    o.point = s * magfem::parse_vector3("--point", args.point);
  o.carry_point = translate && !args.point.empty();
  if (!args.surface_radius.empty())
    o.surface_radius =
        s * magfem::parse_cli_number("--surface-radius", args.surface_radius.c_str());
  o.analytic = args.analytic_sweep;
  o.jobs = args.jobs;
  o.order = args.overrides.order;
  o.mesh_scale = args.overrides.mesh_scale;
  o.max_memory_gb = args.overrides.max_memory_gb;
  o.world = sweep_world(args);
  const auto checkpoint = sweep_checkpoint(
      o.world, args,
      magfem::checkpoint_identity(
          translate ? "sweep --move" : "sweep --rotate", args.case_file,
          magfem::sweep_checkpoint_options(o, args.axis, args.point, args.surface_radius)));
  o.checkpoint = checkpoint.get();

  magfem::SweepJobs jobs;
  const bool quiet = args.quiet || !o.world.is_root();
  const auto progress = quiet ? magfem::SweepProgress{} : show_progress;
  const auto rows = planar ? magfem::run_sweep_planar(spec, o, progress, &jobs)
                           : magfem::run_sweep(spec, o, progress, &jobs);
  if (!o.world.is_root()) // rank 0 has the rows, and writes and reports them
    return magfem::code_of_root(0);
  magfem::OutputStage stage(args.out_dir);
  stage.write_text("sweep.csv", magfem::sweep_csv(rows, o.motion));
  std::string why;
  magfem::SweepPlotLabels labels;
  if (planar) { // about the sweep's point, per metre of length unless the case has a stack
    const std::string per = spec.stack_length > 0 ? "" : "/m";
    labels.torque = std::string("torque about the point") +
                    (translate ? " moved with the group" : "") + " (N m" + per + ")";
    labels.force = "force on the group (N" + per + ")";
  }
  const bool plotted = magfem::plot_sweep(rows, spec.file + (o.analytic ? " (analytic)" : " (FE)"),
                                          stage.path_for("sweep.png"), why, o.motion, labels);
  if (!plotted)
    std::cerr << "magfem: note: no sweep.png: " << why << "\n";
  nlohmann::ordered_json j;
  magfem::add_provenance(j);
  auto summary = magfem::sweep_summary(spec.file, rows, o, jobs);
  for (auto& [key, value] : summary.items())
    j[key] = std::move(value);
  const int failed = j["failed_positions"].get<int>();
  const double total_s = position_time(rows);
  j["peak_memory_MB"] = magfem::peak_memory_mb();
  stage.write_text("summary.json", j.dump(2) + "\n");
  stage.commit();
  checkpoint->remove();

  const std::string key = magfem::sweep_position_key(o.motion);
  std::printf("%10s %12s %12s %12s %12s %12s %12s %9s\n", key.c_str(), "Tx_Nm", "Ty_Nm", "Tz_Nm",
              "Fx_N", "Fy_N", "Fz_N", "time_s");
  for (const auto& r : rows)
    if (r.ok)
      std::printf("%10.3f %12.5g %12.5g %12.5g %12.5g %12.5g %12.5g %9.2f\n", r.angle_deg,
                  r.torque.x(), r.torque.y(), r.torque.z(), r.force.x(), r.force.y(), r.force.z(),
                  r.seconds);
    else
      std::printf("%10.3f FAILED: %s\n", r.angle_deg, r.error.c_str());
  std::printf("%s\n", magfem::sweep_method_note(rows, o).c_str());
  for (const auto& w : magfem::sweep_warnings(rows, o))
    std::printf("warning  %s\n", w.c_str());
  std::printf("wrote    %s/sweep.csv%s, summary.json (%.1f s of position time)\n",
              args.out_dir.c_str(), plotted ? ", sweep.png" : "", total_s);
  std::fflush(stdout);
  if (failed)
    std::cerr << "magfem: " << failed << " of " << rows.size() << " positions failed\n";
  return magfem::code_of_root(failed ? 3 : 0);
}

// Under mpirun the designs are dealt to the processes, each design's sweep on its process's
// threads (studies/study.hpp).
int run_study(const std::vector<std::string>& arguments) {
  magfem::StudyOptions options = magfem::parse_study_options(arguments);
  options.world = dealt_world("study", "designs", options.sweep.jobs,
                              "sweeps one design at a time, its positions N at once");
  if (!options.world.is_root())
    options.quiet = true;
  return magfem::run_study_command(options);
}

// Under mpirun the catalogue entries are dealt to the processes (validation/validate.hpp).
int run_validate(const std::vector<std::string>& arguments) {
  magfem::ValidateOptions options = magfem::parse_validate_options(arguments);
  options.world = dealt_world("validate", "catalogue entries", options.jobs, "evaluates N at once");
  return magfem::run_validate(options);
}

// Under mpirun (--verify only) the verification solves are dealt to the processes
// (studies/actuator.hpp).
int run_actuator(const std::vector<std::string>& arguments) {
  magfem::ActuatorOptions options = magfem::parse_actuator_options(arguments);
  options.world =
      dealt_world("actuator --verify", "verification solves", 0, "solves one at a time");
  if (options.world.distributed() && !options.coil_pitch.empty())
    throw magfem::InputError("<command line>", 0, "--coil-pitch",
                             "the coil-pitch study runs without mpirun");
  if (!options.world.is_root())
    options.quiet = true;
  return magfem::run_actuator_command(options);
}

int run_compare(const Args& args) {
  const auto ref = magfem::read_probe_csv(args.positional[0]);
  const auto test = magfem::read_probe_csv(args.positional[1]);
  std::vector<magfem::ComponentComparison> rows;
  try {
    rows = magfem::compare_probes(ref, test);
  } catch (const std::invalid_argument& e) {
    throw magfem::InputError(args.positional[1], 0, "", e.what());
  }
  std::printf("%zu points; reference %s\n", ref.rows.size(), args.positional[0].c_str());
  std::printf("%-8s %12s %12s %16s %16s %12s %12s\n", "comp", "rms_ref_T", "rms_test_T",
              "eq3.117_pct", "pointwise_pct", "max_diff_T", "rms_diff_T");
  bool undefined = false;
  for (const auto& c : rows) {
    std::printf("%-8s %12.6g %12.6g ", c.component.c_str(), c.rms_reference, c.rms_test);
    if (c.relative_defined)
      std::printf("%16.4f %16.4f", 100 * c.discrepancy_3117, 100 * c.pointwise_rms);
    else
      std::printf("%16s %16s", "n/a", "n/a"), undefined = true;
    std::printf(" %12.4g %12.4g\n", c.max_abs_difference, c.rms_difference);
  }
  if (undefined)
    std::printf("n/a: the reference component is zero (to round-off); its differences are "
                "absolute only\n");
  return 0;
}

bool is_help(const char* arg) {
  return std::strcmp(arg, "--help") == 0 || std::strcmp(arg, "-h") == 0;
}

// --help, --version, `help [COMMAND]` and `COMMAND --help`: printed to stdout, exit 0.
std::optional<int> answer_help_or_version(int argc, char** argv) {
  if (argc < 2)
    return std::nullopt;
  const std::string first = argv[1];
  if (first == "--version" || first == "-V") {
    std::cout << "magfem " << magfem::magfem_version() << " (commit " << magfem::magfem_git_commit()
              << ")\n";
    return 0;
  }
  if (is_help(argv[1]) || (first == "help" && argc == 2)) {
    std::cout << magfem::usage_overview();
    return 0;
  }
  // The option table of a command, one name a line: what the completion script and the help
  // page must offer (tests/install/check_completion.sh compares them).
  if (first == "help" && argc == 4 && std::strcmp(argv[2], "--list-options") == 0) {
    if (!magfem::command_usage(argv[3]))
      throw magfem::InputError("<command line>", 0, "",
                               std::string("unknown command '") + argv[3] + "'");
    for (const auto& option : magfem::command_options(argv[3]))
      std::cout << option.name << (option.value.empty() ? "" : " " + option.value) << "\n";
    return 0;
  }
  const std::string command = first == "help" ? argv[2] : first;
  const bool asked = first == "help" || (argc >= 3 && is_help(argv[2]));
  if (!asked)
    return std::nullopt;
  if (const auto page = magfem::command_usage(command)) {
    std::cout << *page;
    return 0;
  }
  throw magfem::InputError("<command line>", 0, "",
                           "unknown command '" + command + "'\n" + magfem::usage_overview());
}

// Under mpirun `solve` distributes one case (run_solve starts MPI); `sweep`, `study`,
// `validate` and `actuator --verify` deal their positions, designs, entries or orientations to
// the processes: MPI starts here, with any thread allowed to call it (one thread of rank 0
// deals while others solve), before the options are read, so that a bad option ends every
// process alike (fail()). Any other command with several processes would run once per
// process, each writing the same outputs.
void start_mpi_or_refuse(int argc, char** argv) {
  if (!magfem::launched_by_mpirun() || argc < 2 || std::strcmp(argv[1], "solve") == 0)
    return;
  const std::string command = argv[1];
  const bool verify = command == "actuator" &&
                      std::any_of(argv + 2, argv + argc,
                                  [](const char* a) { return std::strcmp(a, "--verify") == 0; });
  const bool dealt = command == "sweep" || command == "study" || command == "validate" || verify;
  if (!magfem::join_mpi_world(dealt).distributed() || dealt)
    return;
  if (command == "actuator")
    throw magfem::InputError("<command line>", 0, "",
                             "`magfem actuator` runs distributed only with --verify (its FE "
                             "verification solves are dealt to the processes); run it without "
                             "mpirun");
  if (command == "optimize")
    throw magfem::InputError(
        "<command line>", 0, "",
        "`magfem optimize` is sequential (each step is chosen from the designs before it), so "
        "processes would have nothing to share; run it without mpirun, or evaluate a grid of "
        "designs across processes with `mpirun -n N magfem study`");
  throw magfem::InputError(
      "<command line>", 0, "",
      "only `magfem solve`, `sweep`, `study` and `validate` run distributed; run "
      "`magfem " +
          command + "` without mpirun");
}

// The error line on stderr and the exit code. Under mpirun with several processes every
// process that fails says which it is and ends them all: the others may be waiting for it in
// a collective call and would otherwise hang.
int fail(int code, const std::string& line) {
  const magfem::MpiWorld world = magfem::started_mpi_world();
  std::string text = "magfem: ";
  if (world.distributed()) // one write per line: the processes share the terminal
    text += "rank " + std::to_string(world.rank) + " of " + std::to_string(world.size) + ": ";
  std::cerr << text + line + "\n" << std::flush;
  if (world.distributed())
    magfem::abort_mpi_world(code);
  return code;
}

} // namespace

int main(int argc, char** argv) {
  // Before any thread starts: Ctrl-C and kill then leave no partial outputs (exit 130/143).
  magfem::install_interrupt_handler();
  try {
    if (const auto code = answer_help_or_version(argc, argv))
      return *code;
    start_mpi_or_refuse(argc, argv);
    if (argc >= 2 && std::strcmp(argv[1], "materials") == 0)
      return magfem::run_materials_command(std::vector<std::string>(argv + 2, argv + argc));
    if (argc >= 2 && std::strcmp(argv[1], "mesh") == 0)
      return magfem::run_mesh_command(std::vector<std::string>(argv + 2, argv + argc));
    if (argc >= 2 && std::strcmp(argv[1], "validate") == 0)
      return run_validate(std::vector<std::string>(argv + 2, argv + argc));
    if (argc >= 2 && std::strcmp(argv[1], "optimize") == 0)
      return magfem::run_optimize_command(
          magfem::parse_optimize_options(std::vector<std::string>(argv + 2, argv + argc)));
    if (argc >= 2 && std::strcmp(argv[1], "actuator") == 0)
      return run_actuator(std::vector<std::string>(argv + 2, argv + argc));
    if (argc >= 2 && std::strcmp(argv[1], "study") == 0)
      return run_study(std::vector<std::string>(argv + 2, argv + argc));
    const Args args = magfem::parse_command_args(argc, argv);
    if (args.command == "solve")
      return run_solve(args);
    if (args.command == "analytic")
      return run_analytic(args);
    if (args.command == "compare")
      return run_compare(args);
    if (args.command == "sweep")
      return run_sweep(args);
    throw magfem::InputError("<command line>", 0, "",
                             "unknown command '" + args.command + "'\n" + magfem::usage_overview());
  } catch (const magfem::InputError& e) {
    return fail(2, std::string("error: ") + e.what());
  } catch (const magfem::SolveError& e) {
    return fail(3, std::string("solver failed: ") + e.what());
  } catch (const magfem::BackendModuleError& e) {
    return fail(1, std::string("installation error: ") + e.what());
  } catch (const std::exception& e) {
    return fail(1, std::string("internal error: ") + e.what());
  }
}
