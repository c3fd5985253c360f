#pragma once
// `magfem study CASE.yaml --param NAME=START:STEP:END [--param ..] --objective Q [..]
//  [--rotate GROUP --axis A --angles LIST] [--analytic|--fe] [--mesh-scale S] [--order 1|2]
//  [--accuracy PCT [--max-passes N] [--max-unknowns N]] [--jobs N] [--resume] [--out DIR]`:
//  (--mesh-scale, --order and the adaptive options are the FE sweep's, as in `solve`)
// a grid over case-file parameters (casefile/case_parameters.hpp), each design evaluated by a
// sweep (studies/sweep.hpp: analytic by default, the harmonic form where it applies), writing
// DIR/study.csv (one column per parameter, one per objective), study.png and summary.json.
//
// Objectives (torque about the rotation axis, on the rotated group, N m):
//   peak_torque      max over --angles of |T . axis|
//   torque_at:DEG    T . axis at DEG (one position; --angles not needed)
//
// FE: every objective comes with its estimated error (N m, study.csv's `<objective>_err`).
// With the case's `adapt:` or --accuracy every position a design's objectives need is refined
// for its torque (studies/sweep.hpp); a position that stops at a limit first is a warning.
//
// Every finished design is kept in DIR/.magfem-checkpoint.jsonl as it finishes
// (pipeline/run_checkpoint.hpp, the sweep's); --resume restores them and evaluates the rest.
//
// Under mpirun (`mpirun -n N magfem study ...`) the designs are dealt to the processes one at
// a time as each finishes one (studies/position_runner.hpp, the sweep's dealer); rank 0 keeps
// the checkpoint and writes the outputs of the serial run.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "casefile/adapt_spec.hpp"
#include "casefile/case_spec.hpp"
#include "core/option_table.hpp"
#include "studies/sweep.hpp"

namespace magfem {

class RunCheckpoint;

struct StudyParameter {
  std::string name;
  std::vector<double> values; // in the parameter's own unit (as --param gives them)
};

struct StudyObjective {
  enum class Kind { peak_torque, torque_at };
  Kind kind = Kind::peak_torque;
  double angle_deg = 0; // torque_at
  std::string name;     // the column: "peak_torque_Nm", "torque_at_90deg_Nm"
};

struct StudyOptions {
  std::string case_file;
  std::vector<StudyParameter> parameters;
  std::vector<StudyObjective> objectives;
  SweepOptions sweep; // group, axis, angles, analytic, jobs (angles: peak_torque only)
  // --fe: --accuracy, --max-passes, --max-unknowns over each design's `adapt:` section.
  AdaptOverrides adapt;
  std::string out_dir;
  bool quiet = false;  // no progress lines on stderr
  bool resume = false; // continue from the checkpoint in out_dir
  // Reads the case with a design's parameter values; empty: read_case(case_file, ..). Python
  // sets it for a case given as YAML text (magfem.Case.from_dict), which has no file.
  std::function<CaseSpec(const ParameterOverrides&)> read;
  // Under mpirun: the processes the designs are dealt to (studies/position_runner.hpp), each
  // design's sweep on its process's threads (sweep.jobs, else its share of the machine's
  // cores); rank 0 alone gets the designs back and keeps the checkpoint.
  MpiWorld world{};
};

// Parses the arguments after `study`; throws InputError naming the option.
StudyOptions parse_study_options(const std::vector<std::string>& args);
// The options parse_study_options takes (for `magfem help study` and the completion).
std::vector<OptionInfo> study_option_infos();

// An FE design's adaptive refinement, over the positions its objectives need.
struct StudyDesignAdapt {
  int passes = 0;         // the most passes a position took (0: every position on one mesh)
  bool converged = false; // every position reached the accuracy
  long unknowns = 0;      // the largest last mesh of its positions
  double error_pct = 0;   // the largest estimated relative torque error of its positions
  std::vector<double> stopped_deg; // positions that stopped at a limit first
};

struct StudyDesign {
  std::vector<double> parameters; // parallel to StudyOptions::parameters
  std::vector<double> objectives; // parallel to StudyOptions::objectives
  // FE: each objective's estimated error, N m (NaN: none); empty for analytic designs.
  std::vector<double> objective_errors;
  StudyDesignAdapt adapt;
  bool ok = false;
  std::string error;
  std::string method; // sweep_method() of its sweep
  // Largest torque accuracy figure of its positions, N m: the truncation bound of the harmonic
  // form or the estimated quadrature error of the face-pair interaction (0 for FE).
  double torque_accuracy = 0;
  double seconds = 0;
};

// One objective from its command-line text (peak_torque, torque_at:DEG); InputError if unknown.
StudyObjective parse_study_objective(const std::string& text);

// One design: the case read with `values` for options.parameters (in their own units) and
// swept; failures other than bad options are recorded in the design, not thrown.
StudyDesign evaluate_study_design(const StudyOptions& options, const std::vector<double>& values);

// Every design of the grid (the last parameter varies fastest). A design whose case cannot be
// read (e.g. the radii cross) or whose sweep fails is recorded with its message; a bad option
// or a case that fails for every design (unknown parameter, group) throws InputError.
// With a checkpoint, a design it holds is restored instead of evaluated, and every design
// that succeeds is recorded in it as it finishes (failed ones are evaluated again on resume).
// on_design(done, total) after each design; a stop asked through options.sweep.stop starts
// no further design (those returned are the ones done). Under mpirun (options.world) every
// process calls this; rank 0 gets the designs, the others none.
std::vector<StudyDesign>
run_study(const StudyOptions& options, RunCheckpoint* checkpoint = nullptr,
          const std::function<void(int done, int total)>& on_design = nullptr);

// The identity line of a study's checkpoint: the case file's hash, the commit and every
// option that changes a result (values with 17 significant digits; not --jobs, --quiet).
std::string study_checkpoint_identity(const StudyOptions& options);
// Its options part (no case, no commit), for a caller that names the case otherwise (Python's
// cases given as text, or with parameter overrides under the grid).
std::string study_checkpoint_options(const StudyOptions& options);

// study.csv: the parameter names, then the objective names, then (FE) `<objective>_err` for
// each; successful designs only.
std::string study_csv(const StudyOptions& options, const std::vector<StudyDesign>& designs);

// summary.json but the provenance: case, method, group, axis, angles_deg, parameters,
// objectives, designs, failed_designs, failures, seconds, max_torque_error_Nm (analytic),
// adapt (FE designs that adapted: parameters, converged, passes, unknowns) and warnings.
// Also magfem.study's `summary` in Python.
nlohmann::ordered_json study_summary(const StudyOptions& options,
                                     const std::vector<StudyDesign>& designs);

// One warning per adapted design that stopped at a limit before its accuracy.
std::vector<std::string> study_warnings(const StudyOptions& options,
                                        const std::vector<StudyDesign>& designs);

// The command: runs, writes study.csv, study.png (if gnuplot is there) and summary.json
// through one OutputStage, prints a table; returns the exit code (3 if any design failed).
// Keeps the checkpoint while it runs (options.resume: continues from it), removes it after.
int run_study_command(const StudyOptions& options);

} // namespace magfem
