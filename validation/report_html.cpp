// report.html: one self-contained page a reader can take in from the top. A summary with
// links to every failure and finding, the sources as full citations, a compact table (one
// line per entry: figure, short quantity, status, value against the published one, error
// against the tolerance) and, per entry, its own section with the long text and the plot.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "pipeline/build_info.hpp"
#include "studies/gnuplot.hpp"
#include "validation/number_text.hpp"
#include "validation/report_plot.hpp"
#include "validation/report_text.hpp"
#include "validation/validate_report.hpp"

namespace magfem {

namespace {

const char* const page_style =
    "body{font-family:system-ui,sans-serif;font-size:15px;line-height:1.4;max-width:1180px;"
    "margin:auto;padding:0 1.2em 3em;color:#222}"
    "h1{font-size:1.6em}h2{margin-top:1.6em;border-bottom:1px solid #bbb}"
    "code{font-size:.92em;background:#f2f2f2;padding:0 .2em}"
    ".counts span{display:inline-block;padding:.2em .7em;margin-right:.4em;border-radius:4px}"
    ".badge{padding:0 .45em;border-radius:4px;font-size:.9em}"
    ".pass{background:#c8efc8}.fail{background:#f5b5b5}.finding{background:#fde9b0}"
    ".skipped{background:#e6e6e6}"
    "table.entries{border-collapse:collapse;width:100%;table-layout:fixed;font-size:13px}"
    "table.entries td,table.entries th{border-bottom:1px solid #ddd;padding:3px 6px;"
    "white-space:nowrap;overflow:hidden;text-overflow:ellipsis;text-align:left;"
    "vertical-align:top}"
    // Figure and quantity may take two lines: one line cut the words that tell apart the
    // entries of one table (B_rho / B_theta / B_phi at the end of a long description).
    "table.entries td.wrap{white-space:normal}"
    "td.wrap>div{display:-webkit-box;-webkit-line-clamp:2;-webkit-box-orient:vertical;"
    "overflow:hidden}"
    ".counts .zero{background:#f2f2f2;color:#777}"
    // On a narrow window fixed column shares cut the status and the error: let cells wrap.
    "@media (max-width:900px){table.entries{table-layout:auto}"
    "table.entries td,table.entries th{white-space:normal}}"
    "table.entries tr.group th{background:#eef2f7;padding-top:8px}"
    "td.n{font-variant-numeric:tabular-nums}"
    "section.entry{border-top:1px solid #ccc;margin-top:1.2em}"
    "section.entry h3{margin:.6em 0 0}p.id{margin:0 0 .3em}"
    "dl{display:grid;grid-template-columns:7.5em minmax(0,1fr);gap:.2em .8em;margin:.4em 0}"
    "dt{font-weight:600;color:#555}dd{margin:0}"
    ".side-by-side{display:grid;grid-template-columns:minmax(0,1fr) 600px;gap:1.2em}"
    "@media (max-width:1100px){.side-by-side{grid-template-columns:minmax(0,1fr)}}"
    ".figures{display:grid;grid-template-columns:repeat(auto-fit,minmax(420px,1fr));gap:1em}"
    "figure{margin:.4em 0 .8em}figcaption{font-weight:600;margin-bottom:.2em}"
    "figure svg{max-width:100%;height:auto;display:block}"
    "pre{font-size:12px;overflow-x:auto;background:#f7f7f7;padding:.5em}"
    ".muted{color:#666;font-size:.9em}";

std::string source_anchor(const std::string& file) {
  return "src-" + file.substr(0, file.find('.'));
}

// The run's strings as the page shows them (see report_text.hpp).
struct PageText {
  std::string root; // the project folder: the catalogue's folder's parent
  std::string operator()(const std::string& s) const {
    return html_text(project_relative(s, root));
  }
};

const SourceCitation* citation(const ValidationRun& run, const std::string& file) {
  for (const auto& s : run.sources)
    if (s.file == file)
      return &s;
  return nullptr;
}

std::string cite_link(const ValidationRun& run, const std::string& file) {
  const SourceCitation* c = citation(run, file);
  return "<a href=\"#" + source_anchor(file) + "\">" + html_escape(c ? c->cite : file) + "</a>";
}

std::string status_badge(const std::string& status) {
  return "<span class=\"badge " + status + "\">" + status + "</span>";
}

// The catalogue writes "-" for a ratio: no unit to print.
std::string with_unit(const std::string& number, const std::string& unit) {
  if (unit.empty() || unit == "-")
    return number;
  return number + " " + html_escape(unit);
}

// "12.3 FE, 12.1 analytic vs 12.5 N m": what magfem computed against the published value.
std::string value_vs_reference(const EntryResult& r) {
  const CatalogueEntry& e = *r.entry;
  std::string v;
  if (r.fe)
    v += round_text(*r.fe) + " FE";
  if (r.analytic)
    v += (v.empty() ? "" : ", ") + round_text(*r.analytic) + " analytic";
  if (v.empty())
    return "<span class=muted>not computed</span>";
  return v + " vs " + (e.published ? with_unit(round_text(*e.published), e.unit) : "?");
}

// The FE value's discretisation estimate beside its error, where the entry has one:
// " (FE estimate 0.12 %)", points for a percentage value; an adaptive value whose loop stopped
// at a limit says so. It informs the reader how much of the error the mesh may account for;
// the verdict is the error's alone (but an unconverged value fails: validate.hpp judge).
std::string fe_estimate_text(const EntryResult& r) {
  if (!r.fe)
    return "";
  const bool unconverged = r.eval.fe_adapt && !r.eval.fe_adapt->converged;
  if (!r.discretisation_pct)
    return unconverged ? " <span class=muted>(FE <b>not converged</b>)</span>" : "";
  const bool points = r.entry->check == CatalogueEntry::Check::at_most;
  return " <span class=muted>(FE estimate " + round_text(*r.discretisation_pct, 2) +
         (points ? " points" : " %") + (unconverged ? ", <b>not converged</b>" : "") + ")</span>";
}

// The larger error of the two values against the tolerance: "-0.81 % within &plusmn;3 %", or
// for a value that is itself a percentage "0.0028 % &le; 0.1 %"; then the FE estimate.
std::string error_vs_tolerance(const EntryResult& r) {
  const CatalogueEntry& e = *r.entry;
  std::optional<double> worst;
  for (const auto& err : {r.fe_error_pct, r.analytic_error_pct})
    if (err && (!worst || std::abs(*err) > std::abs(*worst)))
      worst = err;
  if (!worst || e.expect == CatalogueEntry::Expect::skipped)
    return "";
  const std::string err = round_text(*worst, 2) + " %";
  if (e.expect == CatalogueEntry::Expect::finding)
    return err + fe_estimate_text(r) + " <span class=muted>(finding)</span>";
  const bool ok = std::abs(*worst) <= e.tolerance_pct;
  const std::string limit = round_text(e.tolerance_pct, 3) + " %";
  // A signed error against a two-sided band: "-12 % &gt; 10 %" would read as false.
  if (e.check == CatalogueEntry::Check::relative)
    return err + (ok ? " within &plusmn;" : " outside &plusmn;") + limit + fe_estimate_text(r);
  return err + (ok ? " &le; " : " &gt; ") + limit + fe_estimate_text(r);
}

std::string summary(const ValidationRun& run) {
  std::map<std::string, std::vector<const EntryResult*>> by_status;
  for (const auto& r : run.results)
    by_status[r.status].push_back(&r);
  auto n = [&](const char* s) { return by_status.count(s) ? by_status.at(s).size() : 0; };
  char buf[256];
  std::snprintf(
      buf, sizeof buf,
      "<p class=muted>magfem %s (commit %s), %s tier, %zu entries in %.0f s on %d "
      "jobs.</p>\n",
      html_escape(magfem_version()).c_str(), html_escape(magfem_git_commit().substr(0, 12)).c_str(),
      to_string(run.options.tier).c_str(), run.results.size(), run.wall_seconds, run.jobs);
  std::string h = buf;
  h += "<p class=counts>";
  // A count of zero in grey: "0 fail" in red reads as a failure at a glance.
  for (const auto& [status, label] : {std::pair{"pass", " pass"},
                                      {"fail", " fail"},
                                      {"finding", " findings"},
                                      {"skipped", " skipped"}})
    h += "<span class=" + std::string(n(status) ? status : "zero") + ">" +
         std::to_string(n(status)) + label + "</span>";
  h += "</p>\n";
  auto links = [&](const char* status, const char* heading) {
    if (!by_status.count(status))
      return;
    h += "<p><b>" + std::string(heading) + ":</b> ";
    for (std::size_t k = 0; k < by_status.at(status).size(); ++k) {
      const CatalogueEntry& e = *by_status.at(status)[k]->entry;
      h += (k ? ", " : "") + std::string("<a href=\"#") + html_escape(e.id) + "\">" +
           html_escape(e.id) + "</a>";
    }
    h += "</p>\n";
  };
  links("fail", "Failures");
  links("finding", "Findings (published values magfem shows cannot be reproduced as printed)");
  return h;
}

std::string citation_item(const SourceCitation& s) {
  std::string h = "<li id=\"" + source_anchor(s.file) + "\">" + html_escape(s.authors) + ", <i>" +
                  html_escape(s.title) + "</i>, " + html_escape(s.venue) + ", " +
                  html_escape(s.year) + ".";
  if (!s.link.empty())
    h += " <a href=\"" + html_escape(s.link) + "\">" + html_escape(s.link) + "</a>.";
  h += " <span class=muted>Seed file <code>" + html_escape(s.file) + "</code>";
  return h + (s.note.empty() ? "" : "; " + html_escape(s.note)) + ".</span></li>\n";
}

// The sources this run used, cited in the catalogue's order; a source the catalogue gives no
// citation for (a test catalogue) is still listed, by its file name.
std::string sources_list(const ValidationRun& run) {
  std::vector<std::string> used;
  for (const auto& r : run.results)
    if (std::find(used.begin(), used.end(), r.entry->source) == used.end())
      used.push_back(r.entry->source);
  std::string h = "<h2 id=\"sources\">Sources</h2>\n<ol>\n";
  for (const auto& s : run.sources)
    if (std::find(used.begin(), used.end(), s.file) != used.end())
      h += citation_item(s);
  for (const auto& file : used)
    if (!citation(run, file))
      h += "<li id=\"" + source_anchor(file) + "\"><code>" + html_escape(file) +
           "</code> <span class=muted>(the catalogue gives no citation)</span></li>\n";
  return h + "</ol>\n";
}

std::string table_row(const EntryResult& r) {
  const CatalogueEntry& e = *r.entry;
  return "<tr><td class=wrap><div>" + html_escape(e.section) +
         "</div></td><td class=wrap title=\"" + html_escape(e.quantity) + "\"><div><a href=\"#" +
         html_escape(e.id) + "\">" + html_escape(short_quantity(e.quantity, 120)) +
         "</a></div></td><td>" + status_badge(r.status) + "</td><td class=n>" +
         value_vs_reference(r) +
         // The error may wrap: on one line its FE estimate was cut to "(FE e..." at 1400 px.
         "</td><td class=\"n wrap\">" + error_vs_tolerance(r) + "</td></tr>\n";
}

// The results grouped by source (sources in order of first appearance, entries in run order
// within one): an --only list in any order still gives one group per paper.
std::vector<const EntryResult*> by_source(const ValidationRun& run) {
  std::vector<std::string> order;
  for (const auto& r : run.results)
    if (std::find(order.begin(), order.end(), r.entry->source) == order.end())
      order.push_back(r.entry->source);
  std::vector<const EntryResult*> out;
  for (const auto& source : order)
    for (const auto& r : run.results)
      if (r.entry->source == source)
        out.push_back(&r);
  return out;
}

// Rows grouped by source, each group headed by its citation.
std::string entries_table(const ValidationRun& run) {
  std::string h = "<h2 id=\"table\">Entries</h2>\n<table class=entries><colgroup><col "
                  "style=\"width:13%\"><col style=\"width:40%\"><col style=\"width:7%\"><col "
                  "style=\"width:24%\"><col style=\"width:16%\"></colgroup>\n<tr><th>Figure</th>"
                  "<th>Quantity</th><th>Status</th><th>Value vs published</th><th>Error vs "
                  "tolerance</th></tr>\n";
  std::string group;
  for (const EntryResult* r : by_source(run)) {
    if (r->entry->source != group) {
      group = r->entry->source;
      const SourceCitation* c = citation(run, group);
      h += "<tr class=group><th colspan=5>" + cite_link(run, group) +
           (c ? ": " + html_escape(short_quantity(c->title, 90)) : std::string()) + "</th></tr>\n";
    }
    h += table_row(*r);
  }
  return h + "</table>\n<p class=muted>Error: the larger of the FE and analytic errors, in % of "
             "the published value; for entries whose value is itself a percentage (an rms "
             "discrepancy), the value, against its limit. FE estimate: the estimated "
             "discretisation error of the FE value, from the adaptive refinement's passes "
             "(entries solved to an accuracy) or the change from the next coarser mesh (fixed "
             "mesh scales).</p>\n";
}

std::string tolerance_text(const CatalogueEntry& e, const PageText& text) {
  const std::string limit = round_text(e.tolerance_pct, 3) + " %";
  return (e.check == CatalogueEntry::Check::at_most
              ? "at most " + limit
              : "within " + limit + " of the published value") +
         ": " + text(readable_reason(e.tolerance_reason, e.section));
}

// "published 12 N m; analytic 12.365 N m (error 3 %)": one line for what is compared.
std::string values_text(const EntryResult& r) {
  const CatalogueEntry& e = *r.entry;
  std::string s = e.published ? "published " + with_unit(round_text(*e.published, 6), e.unit) : "";
  auto add = [&](const char* what, std::optional<double> v, std::optional<double> err) {
    if (!v)
      return;
    s += (s.empty() ? "" : "; ") + std::string(what) + " " + with_unit(round_text(*v, 5), e.unit);
    if (err && e.check == CatalogueEntry::Check::relative)
      s += " (error " + round_text(*err, 2) + " %)";
  };
  add("FE", r.fe, r.fe_error_pct);
  add("analytic", r.analytic, r.analytic_error_pct);
  if (r.discretisation_pct)
    s += std::string("; discretisation estimate (") +
         (r.eval.fe_adapt ? "adaptive refinement's" : "change from the next coarser mesh") + ") " +
         round_text(*r.discretisation_pct, 2) +
         (e.check == CatalogueEntry::Check::at_most ? " points" : " %");
  return s;
}

// How the FE value was meshed: "solved adaptively to 1 % on probes.midgap: 2 passes, 92363
// unknowns, converged" or "fixed mesh scales", then the catalogue's reason.
std::string fe_mesh_text(const EntryResult& r, const PageText& text) {
  const CatalogueEntry& e = *r.entry;
  if (!r.fe || e.fe_reason.empty())
    return "";
  std::string s;
  if (const auto& a = r.eval.fe_adapt) {
    s = "solved adaptively to " + round_text(a->accuracy_pct, 3) + " % on " +
        html_escape(e.fe_accuracy ? e.fe_accuracy->quantity : std::string("?")) + ": " +
        std::to_string(a->passes) + " passes, " +
        (r.eval.fe_unknowns ? std::to_string(*r.eval.fe_unknowns) + " unknowns, " : "") +
        (a->converged ? "converged" : "<b>not converged</b> (" + html_escape(a->stop_reason) + ")");
  } else {
    s = "fixed mesh scales" + (r.eval.fe_unknowns
                                   ? " (" + std::to_string(*r.eval.fe_unknowns) + " unknowns)"
                                   : std::string());
  }
  return s + ". " + (r.eval.fe_adapt ? "Why this accuracy: " : "Why fixed: ") + text(e.fe_reason);
}

std::string entry_facts(const EntryResult& r, const ValidationRun& run, const PageText& text) {
  const CatalogueEntry& e = *r.entry;
  std::string h = "<dl>\n<dt>Source</dt><dd>" + cite_link(run, e.source) + ", " +
                  html_escape(e.section) + "</dd>\n";
  if (!e.paper.empty())
    h += "<dt>The paper</dt><dd>" + text(e.paper) + "</dd>\n";
  const std::string values = values_text(r);
  if (!values.empty())
    h += "<dt>Values</dt><dd>" + values + "</dd>\n";
  if (r.status != "skipped")
    h += "<dt>Tolerance</dt><dd>" + tolerance_text(e, text) + "</dd>\n";
  if (!r.eval.method.empty())
    h += "<dt>Method</dt><dd>" + text(r.eval.method) + "</dd>\n";
  if (!e.case_file.empty())
    h += "<dt>Case</dt><dd><code>" + text(e.case_file) + "</code></dd>\n";
  if (const std::string mesh = fe_mesh_text(r, text); !mesh.empty())
    h += "<dt>FE mesh</dt><dd>" + mesh + "</dd>\n";
  if (e.expect == CatalogueEntry::Expect::finding)
    h += "<dt>Finding</dt><dd>" + text(e.reason) + "</dd>\n";
  if (!r.note.empty())
    h += std::string("<dt>") + (r.status == "skipped" ? "Skipped" : "Note") + "</dt><dd>" +
         text(r.note) + "</dd>\n";
  return h + "</dl>\n";
}

// A plot's identity, so that entries sharing one figure's curve draw it once.
std::string plot_key(const Plot& p) {
  std::string k = p.title + '\n' + p.x_label + '\n' + p.y_label;
  for (const auto& s : p.series) {
    k += '\n' + s.name + (s.points_only ? "*" : "");
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      k += ' ' + round_text(s.x[i], 8) + ',' + round_text(s.y[i], 8);
  }
  return k;
}

struct PlotDrawer {
  bool available = false;
  std::string unavailable_why;
  std::map<std::string, std::string> drawn; // plot key -> entry id that shows it
  int count = 0;

  std::string figure(const Plot& p, const std::string& entry_id, const PageText& text) {
    const std::string key = plot_key(p);
    if (const auto it = drawn.find(key); it != drawn.end())
      return "<p class=muted>Plot " + text(p.title) + ": shown with <a href=\"#" +
             html_escape(it->second) + "\">" + html_escape(it->second) + "</a>.</p>\n";
    std::string why = unavailable_why;
    const std::string svg =
        available ? plot_svg(p, "p" + std::to_string(count++) + "_", why) : std::string();
    if (svg.empty())
      return "<p class=muted>Plot " + text(p.title) + " not drawn: " + html_escape(why) + ".</p>\n";
    drawn.emplace(key, entry_id);
    return "<figure><figcaption>" + text(p.title) + "</figcaption>\n" + svg + "</figure>\n";
  }
};

// One plot sits beside the facts on a wide window (below them on a narrow one), so that the
// page stays short without shrinking it; two or more go in a row below the facts instead of
// a tall column beside a short text.
std::string entry_section(const EntryResult& r, const ValidationRun& run, const PageText& text,
                          PlotDrawer& plots) {
  const CatalogueEntry& e = *r.entry;
  std::string facts = entry_facts(r, run, text);
  if (!r.eval.details.empty())
    facts += "<details><summary>Run details</summary><pre>" +
             html_escape(project_relative(r.eval.details.dump(1), text.root)) +
             "</pre></details>\n";
  std::string figures;
  for (const auto& p : r.eval.plots)
    figures += plots.figure(p, e.id, text);
  std::size_t n_figures = 0;
  for (auto p = figures.find("<figure>"); p != std::string::npos;
       p = figures.find("<figure>", p + 1))
    ++n_figures;
  std::string body = facts;
  if (n_figures == 1 || (n_figures == 0 && !figures.empty()))
    body = "<div class=side-by-side><div>" + facts + "</div><div>" + figures + "</div></div>\n";
  else if (n_figures > 1)
    body = facts + "<div class=figures>" + figures + "</div>\n";
  return "<section class=entry id=\"" + html_escape(e.id) + "\">\n<h3>" + status_badge(r.status) +
         " " + text(e.quantity) + "</h3>\n<p class=\"muted id\"><code>" + html_escape(e.id) +
         "</code> &middot; <a href=\"#table\">back to the table</a></p>\n" + body + "</section>\n";
}

std::string project_root(const std::string& catalogue_file) {
  if (catalogue_file.empty())
    return "";
  std::error_code ec;
  const auto abs = std::filesystem::weakly_canonical(catalogue_file, ec);
  return (ec ? std::filesystem::absolute(catalogue_file) : abs)
      .parent_path()
      .parent_path()
      .string();
}

} // namespace

std::string validation_html(const ValidationRun& run) {
  const PageText text{project_root(run.catalogue_file)};
  PlotDrawer plots;
  plots.available = gnuplot_available(plots.unavailable_why);
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
                  "<meta name=\"viewport\" content=\"width=device-width\">"
                  "<title>magfem validation report</title>\n<style>" +
                  std::string(page_style) + "</style></head><body>\n" +
                  "<h1>magfem against the published figures</h1>\n" + summary(run) +
                  sources_list(run) + entries_table(run) + "<h2>Entries in detail</h2>\n";
  for (const EntryResult* r : by_source(run))
    h += entry_section(*r, run, text, plots);
  return h + "</body></html>\n";
}

} // namespace magfem
