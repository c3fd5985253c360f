#include "validation/validate.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <numeric>
#include <set>
#include <sstream>

#include "core/input_error.hpp"
#include "core/output_stage.hpp"
#include "pipeline/build_info.hpp"
#include "pipeline/run_checkpoint.hpp"
#include "studies/position_runner.hpp"
#include "validation/validate_checkpoint.hpp"
#include "validation/validate_report.hpp"

namespace magfem {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

const std::string cli = "<command line>";

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty())
      out.push_back(item);
  return out;
}

std::string default_catalogue() {
  if (const auto share = installed_data_dir())
    return (*share / "validation" / "catalogue.yaml").string();
  if (std::filesystem::is_regular_file("validation/catalogue.yaml"))
    return "validation/catalogue.yaml";
  return std::string(MAGFEM_SOURCE_DIR) + "/validation/catalogue.yaml";
}

std::vector<const CatalogueEntry*> select(const Catalogue& c, const ValidateOptions& o) {
  std::vector<const CatalogueEntry*> out;
  if (!o.only.empty()) {
    for (const auto& id : o.only) {
      const CatalogueEntry* found = nullptr;
      for (const auto& e : c.entries)
        if (e.id == id)
          found = &e;
      if (!found)
        throw InputError(cli, 0, "--only", "no catalogue entry '" + id + "' in " + c.file);
      out.push_back(found);
    }
    return out;
  }
  for (const auto& e : c.entries)
    if (o.source.empty() || e.source.rfind(o.source, 0) == 0)
      out.push_back(&e);
  if (out.empty())
    throw InputError(cli, 0, "--source", "no catalogue entry from source '" + o.source + "'");
  return out;
}

std::optional<double> error_pct(const CatalogueEntry& e, std::optional<double> value) {
  if (!value)
    return std::nullopt;
  if (e.check == CatalogueEntry::Check::at_most)
    return *value;
  return 100 * (*value - *e.published) / std::abs(*e.published);
}

void evaluate(EntryResult& r, ValidationTier tier, ComputeCache& cache) {
  const CatalogueEntry& e = *r.entry;
  if (e.expect == CatalogueEntry::Expect::skipped) {
    r.status = "skipped";
    r.note = e.reason;
    return;
  }
  if (tier == ValidationTier::quick && e.tier == ValidationTier::full) {
    r.status = "skipped";
    r.note = "full tier only (magfem validate --tier full)";
    return;
  }
  const auto t0 = Clock::now();
  try {
    const EvalContext ctx{e, tier, cache};
    r.eval = evaluator_registry().at(e.evaluator).run(ctx);
    r.fe = r.eval.fe;
    r.analytic = r.eval.analytic;
    judge(r);
    if (!r.fe && e.evaluate && e.evaluate->has("fe") && ctx.fe_meshes().empty())
      r.note = "FE in --tier full only";
  } catch (const std::exception& ex) {
    r.status = "fail";
    r.note = std::string("error: ") + ex.what();
  }
  r.seconds = since(t0);
}

} // namespace

void judge(EntryResult& r) {
  const CatalogueEntry& e = *r.entry;
  r.fe_error_pct = error_pct(e, r.fe);
  r.analytic_error_pct = error_pct(e, r.analytic);
  // Discretisation estimate: an adaptive value's is the loop's estimate for its quantity (the
  // solves' relative estimates summed, adapt_loop.hpp; for at_most entries, whose value is an
  // rms difference in % of the field, a relative field error of x % moves it by about x
  // points); a fixed-scale value's is the change from the next coarser mesh, in % of the FE
  // value (in points for at_most entries).
  if (r.fe && r.eval.fe_adapt) {
    if (std::isfinite(r.eval.fe_adapt->estimate_pct))
      r.discretisation_pct = r.eval.fe_adapt->estimate_pct;
  } else if (r.fe && r.eval.fe_coarse) {
    const double change = std::abs(*r.fe - *r.eval.fe_coarse);
    if (e.check == CatalogueEntry::Check::at_most)
      r.discretisation_pct = change;
    else if (*r.fe != 0)
      r.discretisation_pct = 100 * change / std::abs(*r.fe);
  }
  if (!r.fe && !r.analytic) {
    r.status = "fail";
    r.note = "the evaluator computed nothing";
    return;
  }
  if (e.expect == CatalogueEntry::Expect::finding) {
    r.status = "finding";
    if (r.fe && r.eval.fe_adapt && !r.eval.fe_adapt->converged)
      r.note = unconverged_note(*r.eval.fe_adapt);
    return;
  }
  bool ok = true;
  for (const auto& err : {r.fe_error_pct, r.analytic_error_pct})
    if (err && !(std::abs(*err) <= e.tolerance_pct))
      ok = false;
  r.status = ok ? "pass" : "fail";
  // An FE value short of its accuracy is not a verdict the catalogue asked for: a limit (passes,
  // unknowns, memory) stopped the loop, so the value may still carry an error the tolerance
  // cannot absorb. Not a silent pass.
  if (r.fe && r.eval.fe_adapt && !r.eval.fe_adapt->converged) {
    r.status = "fail";
    r.note = unconverged_note(*r.eval.fe_adapt);
  }
}

std::string unconverged_note(const FeAdaptOutcome& a) {
  char buf[160];
  std::snprintf(
      buf, sizeof buf,
      "FE not converged: adaptive refinement stopped before %.3g %% after %d pass(es), estimate ",
      a.accuracy_pct, a.passes);
  std::string s = buf;
  if (std::isfinite(a.estimate_pct)) {
    std::snprintf(buf, sizeof buf, "%.3g %%", a.estimate_pct);
    s += buf;
  } else {
    s += "unknown";
  }
  return s + " (" + a.stop_reason + ")";
}

namespace {

ValidationTier parse_tier(const std::string& option, const std::string& text) {
  if (text == "quick")
    return ValidationTier::quick;
  if (text == "full")
    return ValidationTier::full;
  throw InputError(cli, 0, option, "must be quick or full, got '" + text + "'");
}

int parse_jobs(const std::string& option, const std::string& text) {
  int jobs = 0;
  try {
    jobs = std::stoi(text);
  } catch (const std::exception&) {
    throw InputError(cli, 0, option, "expected a number, got '" + text + "'");
  }
  if (jobs < 0)
    throw InputError(cli, 0, option, "must be >= 0");
  return jobs;
}

const OptionTable<ValidateOptions>& validate_option_table() {
  using O = ValidateOptions;
  using S = const std::string&;
  static const auto table =
      OptionTable<O>("validate")
          .value("--tier", "quick|full", [](O& o, S opt, S v) { o.tier = parse_tier(opt, v); })
          .value("--only", "ID,ID,...", [](O& o, S, S v) { o.only = split_list(v); })
          .value("--source", "SEED", [](O& o, S, S v) { o.source = v; })
          .value("--jobs", "N", [](O& o, S opt, S v) { o.jobs = parse_jobs(opt, v); })
          .flag("--resume", [](O& o, S, S) { o.resume = true; })
          .value("--catalogue", "FILE.yaml", [](O& o, S, S v) { o.catalogue = v; })
          .value("--out", "DIR", [](O& o, S, S v) { o.out_dir = v; });
  return table;
}

} // namespace

std::vector<OptionInfo> validate_option_infos() {
  return validate_option_table().options();
}

ValidateOptions parse_validate_options(const std::vector<std::string>& args) {
  ValidateOptions o;
  const std::vector<std::string> positional = validate_option_table().parse(args, o);
  if (!positional.empty())
    throw InputError(cli, 0, positional[0], "validate takes no arguments, only options");
  if (!o.only.empty() && !o.source.empty())
    throw InputError(cli, 0, "--only", "give --only or --source, not both");
  return o;
}

ValidationRun select_validation(const ValidateOptions& options) {
  ValidationRun run;
  run.options = options;
  run.catalogue_file = options.catalogue.empty() ? default_catalogue() : options.catalogue;
  run.catalogue = std::make_shared<const Catalogue>(read_catalogue(run.catalogue_file));
  run.sources = run.catalogue->sources;
  const auto selected = select(*run.catalogue, options);
  run.results.resize(selected.size());
  for (std::size_t i = 0; i < selected.size(); ++i)
    run.results[i].entry = selected[i];
  const int cores = threads_per_process(options.world); // every core in a serial run
  run.jobs = std::max(
      1, std::min<int>(options.jobs > 0 ? options.jobs : cores, static_cast<int>(selected.size())));
  return run;
}

namespace {

// An entry as the item runner carries it (studies/position_runner.hpp): ok false for a
// failed entry, which is reported but not kept in the checkpoint (--resume evaluates it
// again).
struct EntryRow {
  EntryResult result;
  bool ok = false;
  std::string error;
  double seconds = 0;
};

} // namespace

void evaluate_validation(ValidationRun& run, RunCheckpoint* checkpoint,
                         const ValidationProgress& progress, std::stop_token stop) {
  const auto t_start = Clock::now();
  ComputeCache cache; // this process's: under mpirun each process computes what it needs
  std::vector<std::size_t> items(run.results.size());
  std::iota(items.begin(), items.end(), std::size_t{0});
  const PositionCodec<EntryRow, std::size_t> codec{
      [](const EntryRow& row) { return entry_to_checkpoint(row.result); },
      [&](const nlohmann::json& j, const std::size_t& i) -> std::optional<EntryRow> {
        EntryRow row;
        row.result.entry = run.results[i].entry;
        try {
          entry_from_checkpoint(j, row.result);
        } catch (const std::exception&) { // a record of another shape: evaluate again
          return std::nullopt;
        }
        row.ok = row.result.status != "fail";
        return row;
      },
      [&](const std::size_t& i) { return run.results[i].entry->id; }};
  auto rows = run_items<EntryRow, std::size_t>(
      items, run.jobs, checkpoint, codec,
      [&](EntryRow& row, const std::size_t& i) {
        row.result.entry = run.results[i].entry;
        evaluate(row.result, run.options.tier, cache);
        row.ok = row.result.status != "fail";
      },
      [&](const EntryRow& row, int done, int, bool restored) {
        if (progress)
          progress(row.result, done, since(t_start), restored);
      },
      run.options.world, stop);
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].result.entry) // not stopped before it started
      run.results[i] = std::move(rows[i].result);
  run.wall_seconds = since(t_start);
}

std::string validation_checkpoint_identity(const ValidationRun& run) {
  const ValidateOptions& o = run.options;
  std::string selection = "tier=" + to_string(o.tier) + " source=" + o.source + " only=";
  for (const auto& id : o.only)
    selection += id + ",";
  return checkpoint_identity("validate", run.catalogue_file, selection);
}

int run_validate(const ValidateOptions& options) {
  ValidationRun run = select_validation(options);
  // Finished entries go to a checkpoint as they finish, so that an interrupted run continues
  // with --resume (failed entries are evaluated again). Under mpirun rank 0 alone keeps it
  // (the other processes send it their entries).
  std::optional<RunCheckpoint> checkpoint;
  if (options.world.is_root())
    checkpoint.emplace(options.out_dir, validation_checkpoint_identity(run), options.resume);
  evaluate_validation(run, checkpoint ? &*checkpoint : nullptr,
                      [&](const EntryResult& r, int done, double elapsed_s, bool resumed) {
                        std::fprintf(stderr, "[%3d/%zu] %-8s %-44s %7.1f s  (elapsed %6.1f s)%s\n",
                                     done, run.results.size(), r.status.c_str(),
                                     r.entry->id.c_str(), r.seconds, elapsed_s,
                                     resumed ? " resumed" : "");
                        // Why, where the report would be the only place to say it (an error,
                        // an FE value short of its accuracy).
                        if (r.status == "fail" && !r.note.empty())
                          std::fprintf(stderr, "          %s\n", r.note.c_str());
                      });

  if (!options.world.is_root()) // rank 0 has the results, and writes and reports them
    return code_of_root(0);
  std::filesystem::create_directories(options.out_dir);
  OutputStage stage(options.out_dir, "results.csv");
  write_validation_outputs(run, stage);
  stage.commit();
  checkpoint->remove();

  std::map<std::string, int> counts;
  std::vector<std::string> failed;
  for (const auto& r : run.results) {
    ++counts[r.status];
    if (r.status == "fail")
      failed.push_back(r.entry->id);
  }
  std::printf("%zu entries in %.1f s (%s tier, %d jobs): %d pass, %d fail, %d finding, %d skipped\n"
              "wrote    %s/results.csv, results.json, report.md, report.html\n",
              run.results.size(), run.wall_seconds, to_string(options.tier).c_str(), run.jobs,
              counts["pass"], counts["fail"], counts["finding"], counts["skipped"],
              options.out_dir.c_str());
  std::fflush(stdout);
  if (!failed.empty()) {
    std::cerr << "magfem: validation failed:";
    for (const auto& id : failed)
      std::cerr << " " << id;
    std::cerr << "\n";
  }
  return code_of_root(failed.empty() ? 0 : 4);
}

} // namespace magfem
