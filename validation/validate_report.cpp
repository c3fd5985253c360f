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
    "analytic_error_pct,status,seconds";

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

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out += c;
    }
  }
  return out;
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

std::string check_text(const CatalogueEntry& e) {
  char buf[128];
  if (e.check == CatalogueEntry::Check::at_most)
    std::snprintf(buf, sizeof buf, "<= %g %%", e.tolerance_pct);
  else
    std::snprintf(buf, sizeof buf, "within %g %% of the published value", e.tolerance_pct);
  return buf;
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
                                            num(r.seconds, "%.2f")};
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
  out += "\nFE disc. %: change of the FE value from the next coarser mesh (discretisation error "
         "estimate; points for entries whose value is a percentage). at_most entries (tol "
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

std::string plot_svg(const Plot& plot) {
  const double W = 640, H = 360, L = 70, R = 160, T = 30, B = 50;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const auto& s : plot.series)
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      x0 = std::min(x0, s.x[i]), x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i]), y1 = std::max(y1, s.y[i]);
    }
  if (!(x1 > x0))
    x0 -= 1, x1 += 1;
  if (!(y1 > y0))
    y0 -= 1, y1 += 1;
  const double pad = 0.05 * (y1 - y0);
  y0 -= pad, y1 += pad;
  auto px = [&](double x) { return L + (x - x0) / (x1 - x0) * (W - L - R); };
  auto py = [&](double y) { return H - B - (y - y0) / (y1 - y0) * (H - T - B); };
  char buf[256];
  std::string svg;
  std::snprintf(buf, sizeof buf,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%g\" height=\"%g\" "
                "font-family=\"sans-serif\" font-size=\"11\">\n",
                W, H);
  svg += buf;
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  std::snprintf(buf, sizeof buf, "<text x=\"%g\" y=\"18\" font-size=\"13\">", L);
  svg += buf + html_escape(plot.title) + "</text>\n";
  // Axes with five ticks each.
  for (int k = 0; k <= 4; ++k) {
    const double xv = x0 + k * (x1 - x0) / 4, yv = y0 + k * (y1 - y0) / 4;
    std::snprintf(buf, sizeof buf,
                  "<line x1=\"%.1f\" y1=\"%g\" x2=\"%.1f\" y2=\"%g\" stroke=\"#ddd\"/>"
                  "<text x=\"%.1f\" y=\"%g\" text-anchor=\"middle\">%.4g</text>\n",
                  px(xv), T, px(xv), H - B, px(xv), H - B + 14, xv);
    svg += buf;
    std::snprintf(buf, sizeof buf,
                  "<line x1=\"%g\" y1=\"%.1f\" x2=\"%g\" y2=\"%.1f\" stroke=\"#ddd\"/>"
                  "<text x=\"%g\" y=\"%.1f\" text-anchor=\"end\">%.4g</text>\n",
                  L, py(yv), W - R, py(yv), L - 4, py(yv) + 4, yv);
    svg += buf;
  }
  std::snprintf(
      buf, sizeof buf,
      "<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"none\" stroke=\"black\"/>\n", L, T,
      W - L - R, H - T - B);
  svg += buf;
  std::snprintf(buf, sizeof buf, "<text x=\"%g\" y=\"%g\" text-anchor=\"middle\">", (L + W - R) / 2,
                H - 12);
  svg += buf + html_escape(plot.x_label) + "</text>\n";
  std::snprintf(buf, sizeof buf,
                "<text transform=\"translate(14,%g) rotate(-90)\" text-anchor=\"middle\">",
                (T + H - B) / 2);
  svg += buf + html_escape(plot.y_label) + "</text>\n";
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const auto& s = plot.series[k];
    const char* colour = colours[k % 6];
    if (s.points_only) {
      for (std::size_t i = 0; i < s.x.size(); ++i) {
        std::snprintf(buf, sizeof buf,
                      "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"none\" stroke=\"%s\" "
                      "stroke-width=\"2\"/>\n",
                      px(s.x[i]), py(s.y[i]), colour);
        svg += buf;
      }
    } else {
      svg += "<polyline fill=\"none\" stroke-width=\"1.5\" stroke=\"" + std::string(colour) +
             "\" points=\"";
      for (std::size_t i = 0; i < s.x.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%.1f,%.1f ", px(s.x[i]), py(s.y[i]));
        svg += buf;
      }
      svg += "\"/>\n";
    }
    std::snprintf(buf, sizeof buf,
                  "<rect x=\"%g\" y=\"%g\" width=\"12\" height=\"3\" fill=\"%s\"/>"
                  "<text x=\"%g\" y=\"%g\">",
                  W - R + 10, T + 10 + 16.0 * k, colour, W - R + 26, T + 14 + 16.0 * k);
    svg += buf + html_escape(s.name) + "</text>\n";
  }
  return svg + "</svg>\n";
}

std::string validation_html(const ValidationRun& run) {
  std::string h =
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>magfem validation</title>\n"
      "<style>body{font-family:sans-serif;max-width:1100px;margin:auto;padding:1em}"
      "table{border-collapse:collapse;font-size:12px}td,th{border:1px solid #ccc;padding:2px 5px}"
      "td.n{text-align:right}.pass{background:#c8efc8}.fail{background:#f5b5b5}"
      ".finding{background:#fde9b0}.skipped{background:#e6e6e6}"
      "section{border-top:1px solid #999;margin-top:1.5em}</style></head><body>\n";
  h += "<h1>magfem validation against the published figures</h1>\n<p>";
  h += html_escape(validation_markdown(run).substr(0, validation_markdown(run).find('\n')));
  h += "</p>\n<table><tr><th>id</th><th>section</th><th>quantity</th><th>unit</th>"
       "<th>published</th><th>FE</th><th>analytic</th><th>tol %</th><th>FE err %</th>"
       "<th>analytic err %</th><th>FE disc. %</th><th>status</th><th>s</th></tr>\n";
  for (const auto& r : run.results) {
    const CatalogueEntry& e = *r.entry;
    h += "<tr class=\"" + r.status + "\"><td><a href=\"#" + html_escape(e.id) + "\">" +
         html_escape(e.id) + "</a></td><td>" + html_escape(e.section) + "</td><td>" +
         html_escape(e.quantity) + "</td><td>" + html_escape(e.unit) + "</td><td class=n>" +
         num(e.published, "%.4g") + "</td><td class=n>" + num(r.fe, "%.4g") + "</td><td class=n>" +
         num(r.analytic, "%.4g") + "</td><td class=n>" +
         (e.check == CatalogueEntry::Check::at_most && tolerance(r) ? "&le; " : "") +
         num(tolerance(r)) + "</td><td class=n>" + num(r.fe_error_pct, "%.2g") +
         "</td><td class=n>" + num(r.analytic_error_pct, "%.2g") + "</td><td class=n>" +
         num(r.discretisation_pct, "%.2g") + "</td><td>" + r.status + "</td><td class=n>" +
         num(r.seconds, "%.1f") + "</td></tr>\n";
  }
  h += "</table>\n";
  for (const auto& r : run.results) {
    const CatalogueEntry& e = *r.entry;
    h += "<section id=\"" + html_escape(e.id) + "\"><h3>" + html_escape(e.id) + " <span class=\"" +
         r.status + "\">" + r.status + "</span></h3>\n";
    h += "<p><b>Source:</b> " + html_escape(e.source) + ", " + html_escape(e.section) + ". " +
         html_escape(e.paper) + "</p>\n";
    if (!r.eval.method.empty())
      h += "<p><b>How magfem computes it:</b> " + html_escape(r.eval.method) + "</p>\n";
    if (e.expect != CatalogueEntry::Expect::skipped) {
      h += "<p><b>Agreement:</b> published " + num(e.published) + " " + html_escape(e.unit) +
           "; FE " + (r.fe ? num(r.fe) : std::string("not computed")) + ", analytic " +
           (r.analytic ? num(r.analytic) : std::string("not computed")) +
           ". Tolerance: " + check_text(e) + " (" + html_escape(e.tolerance_reason) + ").";
      if (r.discretisation_pct)
        h += " Discretisation estimate (change from the next coarser mesh): " +
             num(r.discretisation_pct, "%.2g") + ".";
      h += "</p>\n";
    }
    if (e.expect != CatalogueEntry::Expect::compute)
      h += "<p><b>" +
           std::string(e.expect == CatalogueEntry::Expect::finding ? "Finding" : "Skipped") +
           ":</b> " + html_escape(e.reason) + "</p>\n";
    if (!r.note.empty())
      h += "<p><b>Note:</b> " + html_escape(r.note) + "</p>\n";
    for (const auto& p : r.eval.plots)
      h += plot_svg(p);
    if (!r.eval.details.empty())
      h += "<details><summary>details</summary><pre>" + html_escape(r.eval.details.dump(1)) +
           "</pre></details>\n";
    h += "</section>\n";
  }
  return h + "</body></html>\n";
}

void write_validation_outputs(const ValidationRun& run, OutputStage& stage) {
  stage.write_text("results.csv", validation_csv(run));
  stage.write_text("results.json", validation_json(run));
  stage.write_text("report.md", validation_markdown(run));
  stage.write_text("report.html", validation_html(run));
}

} // namespace magfem
