// report.html of `magfem validate` (issue 34 item 1): what a reader must be able to rely on.
// No path of the machine that ran the check, no markdown left as text, every paper cited in
// full, every failure and finding linked from the summary, plots with round tick labels and
// legends inside the image. A run is built in memory from the shipped catalogue (no
// evaluator runs), plus one real entry through the binary with a case file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "studies/gnuplot.hpp"
#include "tests/test_paths.hpp"
#include "validation/report_plot.hpp"
#include "validation/report_text.hpp"
#include "validation/validate.hpp"
#include "validation/validate_report.hpp"

using namespace magfem;

namespace {

const std::string source_dir = magfem::test::source_dir();
const std::string catalogue_path = source_dir + "/validation/catalogue.yaml";

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A curve with the awkward numbers the hand-drawn plots printed as ticks (12.98, 9.583,
// -0.6183), a flat round-off series (1e-13) and a long series name.
Plot awkward_plot() {
  Plot p{"Torque about the tilt axis", "theta (deg)", "T_y (N m)", {}};
  PlotSeries curve{"charge model T_y on the outer hemisphere, design of Table 4.2", {}, {}};
  PlotSeries noise{"charge model T_x (zero by symmetry)", {}, {}};
  for (int k = 0; k <= 12; ++k) {
    const double theta = 15.0 * k;
    curve.x.push_back(theta);
    curve.y.push_back(12.98 * std::sin(theta * M_PI / 180) - 0.6183);
    noise.x.push_back(theta);
    noise.y.push_back(1.137e-13 * std::cos(k));
  }
  p.series = {curve, noise, {"published 12 N m amplitude", {90}, {12}, true}};
  return p;
}

// A force that vanishes by symmetry, computed as round-off.
Plot round_off_plot() {
  return {"Axial force",
          "theta (deg)",
          "F_z (N)",
          {{"charge model F_z", {0, 90, 180}, {2.4e-14, -1e-14, 1.8e-13}, false}}};
}

// Nearly flat curves: a constant, and a loss changing by 0.2 % over two pitches.
Plot flat_plot(double a, double b) {
  return {"Nearly flat",
          "coil pitch (deg)",
          "loss (W)",
          {{"loss", {58, 59, 60}, {a, (a + b) / 2, b}, false}}};
}

// The shipped catalogue with a result per entry: the first computed entry fails with an error
// naming an absolute path, two are findings, the rest pass or are skipped as the catalogue
// says. Plots on the failing entry.
struct FakeRun {
  Catalogue catalogue = read_catalogue(catalogue_path);
  ValidationRun run;
  std::vector<std::string> failed, findings;

  FakeRun() {
    run.catalogue_file = catalogue_path;
    run.sources = catalogue.sources;
    for (const auto& e : catalogue.entries) {
      EntryResult r;
      r.entry = &e;
      r.status = e.expect == CatalogueEntry::Expect::skipped   ? "skipped"
                 : e.expect == CatalogueEntry::Expect::finding ? "finding"
                                                               : "pass";
      if (r.status == "skipped")
        r.note = e.reason;
      else
        r.analytic = e.published;
      if (r.status == "pass" && failed.empty()) {
        r.status = "fail";
        r.note = "error: cannot read " + source_dir + "/examples/3d/compensator_table42.yaml";
        r.eval.plots = {awkward_plot(), flat_plot(9.583, 9.583), flat_plot(39.04, 38.97),
                        round_off_plot()};
        failed.push_back(e.id);
      }
      if (r.status == "finding")
        findings.push_back(e.id);
      r.eval.method = "charge model of `" + e.case_file + "`";
      run.results.push_back(r);
    }
  }
};

std::vector<std::string> svgs(const std::string& html) {
  std::vector<std::string> out;
  for (auto p = html.find("<svg"); p != std::string::npos; p = html.find("<svg", p + 1))
    out.push_back(html.substr(p, html.find("</svg>", p) - p));
  return out;
}

// Significant digits of a tick label as printed ("0.025" -> 2, "1e-05" -> 1, "120" -> 2).
int significant_digits(std::string s) {
  if (const auto e = s.find_first_of("eE"); e != std::string::npos)
    s.erase(e);
  std::string digits;
  for (char c : s)
    if (std::isdigit(static_cast<unsigned char>(c)))
      digits += c;
  digits.erase(0, digits.find_first_not_of('0'));
  if (s.find('.') == std::string::npos) // trailing zeros of an integer are not significant
    digits.erase(digits.find_last_not_of('0') + 1);
  return static_cast<int>(digits.size());
}

// The text of every <text> element of a gnuplot SVG (its <tspan>s joined).
std::vector<std::string> svg_texts(const std::string& svg) {
  std::vector<std::string> out;
  static const std::regex text_re("<text[^>]*>([\\s\\S]*?)</text>");
  static const std::regex tag_re("<[^>]*>");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text_re);
       it != std::sregex_iterator(); ++it)
    out.push_back(std::regex_replace((*it)[1].str(), tag_re, ""));
  return out;
}

bool is_number(const std::string& s) {
  static const std::regex number_re("\\s*-?[0-9.]+([eE][-+]?[0-9]+)?\\s*");
  return std::regex_match(s, number_re);
}

void expect_round_ticks(const std::string& svg) {
  int ticks = 0;
  for (const auto& t : svg_texts(svg))
    if (is_number(t)) {
      ++ticks;
      EXPECT_LE(significant_digits(t), 3) << "tick label '" << t << "'";
    }
  EXPECT_GE(ticks, 4) << "no tick labels found in\n" << svg.substr(0, 400);
}

// Every text anchor (gnuplot places each label by a translate) inside the image, and text
// drawn from an anchor rightwards not running past the right edge (0.6 em per character: a
// generous width for the sans fonts browsers pick).
void expect_text_inside(const std::string& svg) {
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, std::regex("width=\"([0-9.]+)\" height=\"([0-9.]+)\"")));
  const double w = std::stod(m[1]), h = std::stod(m[2]);
  static const std::regex label_re("<g transform=\"translate\\(([-0-9.]+),([-0-9.]+)\\)\"[^>]*"
                                   "font-size=\"([0-9.]+)\"[^>]*text-anchor=\"(\\w+)\"[^>]*>\\s*"
                                   "<text>([\\s\\S]*?)</text>");
  static const std::regex tag_re("<[^>]*>");
  int labels = 0;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), label_re);
       it != std::sregex_iterator(); ++it) {
    const double x = std::stod((*it)[1]), y = std::stod((*it)[2]), size = std::stod((*it)[3]);
    const std::string text = std::regex_replace((*it)[5].str(), tag_re, "");
    ++labels;
    EXPECT_TRUE(x >= 0 && x <= w && y >= 0 && y <= h) << "'" << text << "' at " << x << "," << y;
    if ((*it)[4] == "start") {
      EXPECT_LE(x + 0.6 * size * text.size(), w) << "'" << text << "' runs off the image";
    }
  }
  EXPECT_GE(labels, 4) << "no labels found";
}

} // namespace

TEST(ValidateReport, TextHelpers) {
  EXPECT_EQ(html_text("run `magfem validate` **now** <x>"),
            "run <code>magfem validate</code> <b>now</b> &lt;x&gt;");
  EXPECT_EQ(html_text("a stray ` backtick"), "a stray  backtick");
  EXPECT_EQ(project_relative("case /src/tree/examples/3d/a.yaml", "/src/tree"),
            "case examples/3d/a.yaml");
  EXPECT_EQ(project_relative("(/tmp/x/y/examples/3d/a.yaml)", "/src/tree"), "(examples/3d/a.yaml)");
  EXPECT_EQ(project_relative("wrote /tmp/run/err.txt", ""), "wrote err.txt");
  EXPECT_EQ(project_relative("T / I in A/m, (a + b)/2, 1/2, https://doi.org/10.1/x", "/r"),
            "T / I in A/m, (a + b)/2, 1/2, https://doi.org/10.1/x");
  EXPECT_EQ(readable_reason("paper_targets D (3 points); measured", "Table 6.3"),
            "target for Table 6.3 (3 points); measured");
  EXPECT_EQ(readable_reason("paper_targets.md A", "Fig. 4"), "target for Fig. 4");
  EXPECT_EQ(short_quantity("peak mid-gap B_r (69 mm), FE (exact fields)"),
            "peak mid-gap B_r (69 mm), FE");
  EXPECT_LE(short_quantity(std::string(200, 'a') + " b").size(), 60u);
}

TEST(ValidateReport, EveryCatalogueSourceHasAFullCitation) {
  const Catalogue c = read_catalogue(catalogue_path);
  for (const auto& e : c.entries) {
    bool cited = false;
    for (const auto& s : c.sources)
      cited = cited || s.file == e.source;
    EXPECT_TRUE(cited) << e.id << " cites " << e.source;
  }
  for (const auto& s : c.sources)
    for (const std::string* field : {&s.authors, &s.title, &s.venue, &s.year})
      EXPECT_FALSE(field->empty()) << s.file;
}

TEST(ValidateReport, PageIsPlainForAReader) {
  FakeRun f;
  ASSERT_FALSE(f.failed.empty());
  ASSERT_FALSE(f.findings.empty());
  const std::string html = validation_html(f.run);
  EXPECT_EQ(html.find('`'), std::string::npos) << "markdown backtick on the page";
  EXPECT_EQ(html.find(source_dir), std::string::npos) << "absolute path of the checkout";
  EXPECT_EQ(html.find(std::filesystem::temp_directory_path().string() + "/"), std::string::npos);
  EXPECT_EQ(html.find("paper_targets"), std::string::npos) << "internal label";
  EXPECT_NE(html.find("examples/3d/compensator_table42.yaml"), std::string::npos)
      << "the case path, relative to the project";
  for (const auto& s : f.run.sources) {
    EXPECT_NE(html.find(html_escape(s.authors)), std::string::npos) << s.file;
    EXPECT_NE(html.find(html_escape(s.title)), std::string::npos) << s.file;
    EXPECT_NE(html.find(html_escape(s.venue) + ", " + html_escape(s.year)), std::string::npos)
        << s.file;
  }
  // The summary is everything above the sources list: each failure and finding linked there.
  const std::string summary = html.substr(0, html.find("id=\"sources\""));
  for (const auto& ids : {f.failed, f.findings})
    for (const auto& id : ids) {
      EXPECT_NE(summary.find("href=\"#" + id + "\""), std::string::npos) << id;
      EXPECT_NE(html.find("id=\"" + id + "\""), std::string::npos) << "no section for " << id;
    }
}

// The compact table shows an FE entry's discretisation estimate (change from the next coarser
// mesh, in the details already) beside its error, in points for a percentage value; an
// entry without one shows none; the verdict stays the error's.
TEST(ValidateReport, CompactTableShowsTheFeEstimateBesideTheError) {
  FakeRun f;
  EntryResult* relative = nullptr;
  EntryResult* at_most = nullptr;
  EntryResult* plain = nullptr;
  for (auto& r : f.run.results) {
    if (r.status != "pass" || !r.entry->published)
      continue;
    if (r.entry->check == CatalogueEntry::Check::at_most && !at_most)
      at_most = &r;
    else if (r.entry->check == CatalogueEntry::Check::relative && !relative)
      relative = &r;
    else if (r.entry->check == CatalogueEntry::Check::relative && !plain)
      plain = &r;
  }
  ASSERT_TRUE(relative && at_most && plain);
  // An estimate larger than the tolerance must not turn the pass into anything else.
  relative->fe = *relative->entry->published;
  relative->fe_error_pct = 0.0;
  relative->discretisation_pct = 2 * relative->entry->tolerance_pct;
  at_most->fe = 0.5 * at_most->entry->tolerance_pct;
  at_most->fe_error_pct = at_most->fe;
  at_most->discretisation_pct = 0.0123;
  plain->fe = *plain->entry->published;
  plain->fe_error_pct = 0.0;
  const std::string html = validation_html(f.run);
  const auto row = [&](const EntryResult* r) {
    const auto link = html.find("<a href=\"#" + r->entry->id + "\">");
    EXPECT_NE(link, std::string::npos) << r->entry->id;
    const auto start = html.rfind("<tr>", link);
    return html.substr(start, html.find("</tr>", link) - start);
  };
  char expected[64];
  std::snprintf(expected, sizeof expected, "(FE estimate %g %%)",
                relative->discretisation_pct.value());
  const std::string r1 = row(relative);
  EXPECT_NE(r1.find(expected), std::string::npos) << r1;
  EXPECT_NE(r1.find(" within &plusmn;"), std::string::npos) << r1;
  EXPECT_NE(r1.find(">pass<"), std::string::npos) << r1;
  const std::string r2 = row(at_most);
  EXPECT_NE(r2.find("(FE estimate 0.012 points)"), std::string::npos) << r2;
  EXPECT_EQ(row(plain).find("FE estimate"), std::string::npos) << row(plain);
}

TEST(ValidateReport, PlotsHaveRoundTicksAndLegendsInsideTheImage) {
  std::string why;
  if (!gnuplot_available(why))
    GTEST_SKIP() << why;
  const std::string html = validation_html(FakeRun().run);
  const auto plots = svgs(html);
  ASSERT_EQ(plots.size(), 4u);
  for (const auto& svg : plots) {
    expect_round_ticks(svg);
    expect_text_inside(svg);
  }
  EXPECT_NE(plots[0].find("charge model T_y on the outer hemisphere"), std::string::npos)
      << "legend text";
  EXPECT_NE(plots[0].find("id=\"p0_"), std::string::npos) << "ids prefixed per plot";
  EXPECT_NE(plots[1].find("id=\"p1_"), std::string::npos);
  for (const auto& t : svg_texts(plots[3])) {
    if (!is_number(t))
      continue;
    EXPECT_TRUE(std::stod(t) == 0 || std::abs(std::stod(t)) >= 0.1)
        << "round-off drawn as data: tick " << t;
  }
  EXPECT_NE(plots[3].find("zero to round-off"), std::string::npos);
}

// One real entry through the binary: its case file shows relative to the project.
TEST(ValidateReport, RealRunShowsProjectPaths) {
  const auto out = std::filesystem::temp_directory_path() / "magfem_validate_report";
  std::filesystem::remove_all(out);
  const std::string cmd = std::string(magfem::test::magfem_binary()) + " validate --catalogue " +
                          catalogue_path + " --only thesis.c4.t42.torque_90 --out " + out.string() +
                          " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string html = read_text(out / "report.html");
  EXPECT_NE(html.find("<code>examples/3d/compensator_table42.yaml</code>"), std::string::npos);
  EXPECT_EQ(html.find(source_dir), std::string::npos);
  EXPECT_EQ(html.find('`'), std::string::npos);
}
