#pragma once
// `magfem validate`: runs the catalogue of published figures (validation/catalogue.yaml)
// and writes results.csv, results.json, report.md and report.html (all or nothing).
// Exit codes: 0 nothing failed, 4 some entry failed (ids on stderr), 2 bad input.
#include <functional>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "core/option_table.hpp"
#include "solver/mpi_context.hpp"
#include "validation/validate_catalogue.hpp"
#include "validation/validate_evaluators.hpp"

namespace magfem {

class RunCheckpoint;

struct ValidateOptions {
  ValidationTier tier = ValidationTier::quick;
  std::vector<std::string> only; // entry ids; empty = all
  std::string source;            // seed file prefix; empty = all
  int jobs = 0;                  // 0: one per core
  std::string out_dir = "out/validate";
  std::string catalogue; // empty: validation/catalogue.yaml of the source tree
  bool resume = false;   // continue from the checkpoint an interrupted run left
  // Under mpirun: the processes the entries are dealt to (studies/position_runner.hpp), each
  // evaluating its entries on `jobs` threads (0: its share of the machine's cores); rank 0
  // alone keeps the checkpoint and writes the outputs.
  MpiWorld world{};
};

struct EntryResult {
  const CatalogueEntry* entry = nullptr;
  std::string status; // pass, fail, finding, skipped
  std::optional<double> fe, analytic, fe_error_pct, analytic_error_pct;
  std::optional<double> discretisation_pct; // |fe - fe on the next coarser mesh|, % of fe
  double seconds = 0;
  std::string note; // why skipped, the error of a failed entry, FE not in this tier
  EvalResult eval;
};

struct ValidationRun {
  ValidateOptions options;
  std::string catalogue_file;
  std::shared_ptr<const Catalogue> catalogue; // what the results' entries point into
  std::vector<SourceCitation> sources;        // the catalogue's citations (report.html)
  std::vector<EntryResult> results;
  double wall_seconds = 0;
  int jobs = 1;
};

// Parses the options after `validate` (throws InputError).
ValidateOptions parse_validate_options(const std::vector<std::string>& args);
// Its options (for `magfem help validate` and the completion).
std::vector<OptionInfo> validate_option_infos();
// Reads the catalogue and selects the entries of `options` (results with their entry only,
// jobs settled); throws InputError for bad input (unknown id, bad catalogue).
ValidationRun select_validation(const ValidateOptions& options);

// The identity of a selection's checkpoint (pipeline/run_checkpoint.hpp): the tier, the
// selection, the catalogue file's hash and the commit; shared by the command and Python.
std::string validation_checkpoint_identity(const ValidationRun& run);

// After each entry (serialized): the entry's result, how many are done, the seconds since the
// evaluation started and whether the checkpoint had it.
using ValidationProgress =
    std::function<void(const EntryResult& r, int done, double elapsed_s, bool resumed)>;

// Evaluates the selected entries on run.jobs threads, without writing outputs: finished
// entries are taken from `checkpoint` (may be null) and the others recorded there but failed
// ones. A stop asked through `stop` (Ctrl-C in Python) starts no further entry; entries not
// started keep an empty status. Under mpirun (options.world) every process calls this and
// the entries are dealt to them; rank 0 gets the results, the others keep empty ones.
void evaluate_validation(ValidationRun& run, RunCheckpoint* checkpoint,
                         const ValidationProgress& progress = {}, std::stop_token stop = {});

// Selects entries, runs them, writes the outputs; returns the exit code. Throws InputError
// for bad input (unknown id, bad catalogue).
int run_validate(const ValidateOptions& options);

// Status and error columns of one evaluated entry (exposed for tests). An FE value whose
// adaptive solves stopped at a limit fails (a finding keeps its status), with the note of
// unconverged_note.
void judge(EntryResult& r);
// "FE not converged: adaptive refinement stopped before 1 % after 3 pass(es), ..." .
std::string unconverged_note(const FeAdaptOutcome& a);

} // namespace magfem
