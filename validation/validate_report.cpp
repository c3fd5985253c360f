#include "validation/validate_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include <nlohmann/json.hpp>

#include "pipeline/build_info.hpp"

namespace magfem {

const char* const validation_csv_header =
    "id,source,section,quantity,unit,published,fe,analytic,tolerance_pct,fe_error_pct,"
    "analytic_error_pct,status,seconds,passes,unknowns,converged";

namespace {

std::string num(std::optional<double> v, const char* fmt = "%.6g") {
  if (!v)
    return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, *v);
  return buf;
}

std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos)
    return s;
  std::string out = "\"";
  for (char c : s)
    out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string md_cell(const std::string& s) {
  std::string out;
  for (char c : s)
    out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::optional<double> tolerance(const EntryResult& r) {
  if (r.entry->expect == CatalogueEntry::Expect::skipped)
    return std::nullopt;
  return r.entry->tolerance_pct;
}

// The adaptive FE columns: passes and converged are empty for a value on fixed mesh scales
// (or no FE value); unknowns is the largest FE mesh behind the value either way.
std::optional<double> passes(const EntryResult& r) {
  if (!r.fe || !r.eval.fe_adapt)
    return std::nullopt;
  return r.eval.fe_adapt->passes;
}
std::optional<double> unknowns(const EntryResult& r) {
  if (!r.fe || !r.eval.fe_unknowns)
    return std::nullopt;
  return static_cast<double>(*r.eval.fe_unknowns);
}
std::string converged(const EntryResult& r) {
  if (!r.fe || !r.eval.fe_adapt)
    return "";
  return r.eval.fe_adapt->converged ? "yes" : "no";
}

std::map<std::string, int> counts(const ValidationRun& run) {
  std::map<std::string, int> c;
  for (const auto& r : run.results)
    ++c[r.status];
  return c;
}

} // namespace

std::string validation_csv(const ValidationRun& run) {
  std::string out = std::string(validation_csv_header) + "\n";
  for (const auto& r : run.results) {
    const CatalogueEntry& e = *r.entry;
    const std::vector<std::string> cells = {e.id,
                                            e.source,
                                            e.section,
                                            e.quantity,
                                            e.unit,
                                            num(e.published),
                                            num(r.fe),
                                            num(r.analytic),
                                            num(tolerance(r)),
                                            num(r.fe_error_pct, "%.4g"),
                                            num(r.analytic_error_pct, "%.4g"),
                                            r.status,
                                            num(r.seconds, "%.2f"),
                                            num(passes(r), "%.0f"),
                                            num(unknowns(r), "%.0f"),
                                            converged(r)};
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (i)
        out += ',';
      out += csv_cell(cells[i]);
    }
    out += "\n";
  }
  return out;
}

std::string validation_json(const ValidationRun& run) {
  using json = nlohmann::ordered_json;
  auto opt = [](std::optional<double> v) { return v ? json(*v) : json(nullptr); };
  json j;
  j["magfem_version"] = magfem_version();
  j["git_commit"] = magfem_git_commit(); // kept for readers of the first format
  j["commit"] = magfem_git_commit();
  j["catalogue"] = run.catalogue_file;
  j["tier"] = to_string(run.options.tier);
  j["jobs"] = run.jobs;
  j["wall_seconds"] = run.wall_seconds;
  json summary = json::object();
  for (const auto& [k, v] : counts(run))
    summary[k] = v;
  j["summary"] = summary;
  j["entries"] = json::array();
  for (const auto& r : run.results) {
    const CatalogueEntry& e = *r.entry;
    json x;
    x["id"] = e.id;
    x["source"] = e.source;
    x["section"] = e.section;
    x["quantity"] = e.quantity;
    x["unit"] = e.unit;
    x["published"] = opt(e.published);
    x["fe"] = opt(r.fe);
    x["analytic"] = opt(r.analytic);
    x["tolerance_pct"] = opt(tolerance(r));
    x["fe_error_pct"] = opt(r.fe_error_pct);
    x["analytic_error_pct"] = opt(r.analytic_error_pct);
    x["status"] = r.status;
    x["seconds"] = r.seconds;
    x["check"] = to_string(e.check);
    x["tolerance_reason"] = e.tolerance_reason;
    x["expect"] = to_string(e.expect);
    x["entry_tier"] = to_string(e.tier);
    if (!e.reason.empty())
      x["reason"] = e.reason;
    if (!r.note.empty())
      x["note"] = r.note;
    x["fe_coarse"] = opt(r.eval.fe_coarse);
    x["discretisation_pct"] = opt(r.discretisation_pct);
    x["passes"] = opt(passes(r));
    x["unknowns"] = opt(unknowns(r));
    if (r.fe && r.eval.fe_adapt) {
      x["converged"] = r.eval.fe_adapt->converged;
      x["accuracy_pct"] = r.eval.fe_adapt->accuracy_pct;
      if (!r.eval.fe_adapt->converged)
        x["stop_reason"] = r.eval.fe_adapt->stop_reason;
    }
    if (!e.fe_reason.empty())
      x["fe_reason"] = e.fe_reason;
    x["evaluator"] = e.evaluator;
    x["evaluator_quantity"] = e.evaluator_quantity;
    if (!e.case_file.empty())
      x["case"] = e.case_file;
    x["method"] = r.eval.method;
    x["details"] = r.eval.details; // FE settings, mesh sizes, iterations, extra metrics
    j["entries"].push_back(x);
  }
  return j.dump(2) + "\n";
}

std::string validation_markdown(const ValidationRun& run) {
  std::string out;
  char buf[512];
  const auto c = counts(run);
  auto count = [&](const char* k) { return c.count(k) ? c.at(k) : 0; };
  std::snprintf(buf, sizeof buf,
                "magfem %s (commit %s), `--tier %s`, %zu entries in %.0f s on %d jobs: "
                "%d pass, %d fail, %d finding, %d skipped.\n\n",
                magfem_version().c_str(), magfem_git_commit().substr(0, 12).c_str(),
                to_string(run.options.tier).c_str(), run.results.size(), run.wall_seconds, run.jobs,
                count("pass"), count("fail"), count("finding"), count("skipped"));
  out += buf;
  out += "| id | source | section | quantity | unit | published | FE | analytic | tol % | FE err % "
         "| analytic err % | FE disc. % | status |\n";
  out += "|---|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const auto& r : run.results) {
    const CatalogueEntry& e = *r.entry;
    const std::string tol =
        tolerance(r) ? (e.check == CatalogueEntry::Check::at_most ? "<= " : "") + num(tolerance(r))
                     : "";
    out += "| " + md_cell(e.id) + " | " + md_cell(e.source.substr(0, 3)) + " | " +
           md_cell(e.section) + " | " + md_cell(e.quantity) + " | " + md_cell(e.unit) + " | " +
           num(e.published, "%.4g") + " | " + num(r.fe, "%.4g") + " | " + num(r.analytic, "%.4g") +
           " | " + tol + " | " + num(r.fe_error_pct, "%.2g") + " | " +
           num(r.analytic_error_pct, "%.2g") + " | " + num(r.discretisation_pct, "%.2g") + " | " +
           (r.status == "fail" ? "**fail**" : r.status) + " |\n";
  }
  out += "\nFE disc. %: the FE value's discretisation error estimate (adaptive entries: the "
         "refinement loop's estimate for the quantity it refines for; fixed mesh scales: the "
         "change from the next coarser mesh; points for entries whose value is a percentage). "
         "at_most entries (tol "
         "`<= x`) are error measures themselves: their error columns repeat the value.\n";
  std::string notes;
  for (const auto& r : run.results)
    if (!r.note.empty() || r.status == "finding")
      notes += "- `" + r.entry->id + "` (" + r.status +
               "): " + (r.status == "finding" ? r.entry->reason : r.note) + "\n";
  if (!notes.empty())
    out += "\nNotes:\n\n" + notes;
  return out;
}

void write_validation_outputs(const ValidationRun& run, OutputStage& stage) {
  stage.write_text("results.csv", validation_csv(run));
  stage.write_text("results.json", validation_json(run));
  stage.write_text("report.md", validation_markdown(run));
  stage.write_text("report.html", validation_html(run));
}

} // namespace magfem
