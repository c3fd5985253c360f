// `magfem validate` (issue 12): the catalogue reader, the pass/fail rule, the output contract
// and bad input. The quick subset run (label `validation`) recomputes real figures; the
// tolerances asserted are the catalogue's own (the runner's status), not numbers typed here.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <variant>

#include "core/input_error.hpp"
#include "tests/case_helpers.hpp"
#include "tests/test_paths.hpp"
#include "validation/validate.hpp"
#include "validation/validate_report.hpp"

using namespace magfem;

namespace {

const std::string catalogue =
    std::string(magfem::test::source_dir()) + "/validation/catalogue.yaml";

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A temporary catalogue next to which case paths resolve against the source tree.
std::string write_catalogue(const std::string& name, const std::string& entries) {
  const auto dir = std::filesystem::temp_directory_path() / "magfem_tests" / "validate";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << "entries:\n" << entries;
  return path.string();
}

// One Harwin entry (analytic, milliseconds) with a given published value and case line.
std::string harwin_entry(const std::string& id, double published, const std::string& extra = "") {
  std::ostringstream s;
  s << "- id: " << id << "\n"
    << "  source: 000_4b10982579af20cb.txt\n  section: Fig. 4\n  quantity: fitted current\n"
    << "  unit: A/rad\n  published: " << published << "\n  tolerance_pct: 10\n"
    << "  tolerance_reason: test\n"
    << "  evaluate: {evaluator: harwin_fit_current, eq3_current: 6.6e4, radius_mm: 11.5, "
       "band_deg: 15"
    << extra << "}\n";
  return s.str();
}

struct CliRun {
  int code = -1;
  std::string err;
};

CliRun run_cli(const std::string& args, const std::string& tag) {
  const auto err = std::filesystem::temp_directory_path() / ("magfem_validate_" + tag + ".err");
  const std::string cmd = std::string(magfem::test::magfem_binary()) + " validate " + args +
                          " > /dev/null 2> " + err.string();
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(err)};
}

EntryResult judged(CatalogueEntry& e, std::optional<double> fe, std::optional<double> analytic) {
  EntryResult r;
  r.entry = &e;
  r.eval.fe = fe;
  r.eval.analytic = analytic;
  r.fe = fe;
  r.analytic = analytic;
  judge(r);
  return r;
}

// An entry published as 10 with a 5 % tolerance.
CatalogueEntry entry_of_10() {
  CatalogueEntry e;
  e.id = "x";
  e.source = "s";
  e.published = 10.0;
  e.tolerance_pct = 5;
  return e;
}

// A result of `e` with the FE value `fe` (not judged yet).
EntryResult fe_value(const CatalogueEntry& e, double fe) {
  EntryResult r;
  r.entry = &e;
  r.eval.fe = r.fe = fe;
  return r;
}

} // namespace

TEST(Validate, TheShippedCatalogueReadsAndCoversEverySeed) {
  const Catalogue c = read_catalogue(catalogue);
  ASSERT_GT(c.entries.size(), 30u);
  std::map<std::string, int> per_source;
  int skipped = 0, findings = 0;
  for (const auto& e : c.entries) {
    ++per_source[e.source.substr(0, 3)];
    skipped += e.expect == CatalogueEntry::Expect::skipped;
    findings += e.expect == CatalogueEntry::Expect::finding;
    if (e.expect != CatalogueEntry::Expect::skipped) {
      EXPECT_TRUE(e.published.has_value()) << e.id;
      EXPECT_FALSE(e.tolerance_reason.empty()) << e.id;
    }
  }
  for (const char* seed : {"000", "001", "002", "003"})
    EXPECT_GT(per_source[seed], 0) << "no entry from seed " << seed;
  EXPECT_GT(skipped, 0);
  EXPECT_GE(findings, 3); // the +47 % claim and Harwin's real-magnet Table 1
}

TEST(Validate, JudgeAppliesRelativeAndAtMostTolerances) {
  CatalogueEntry e;
  e.id = "x";
  e.published = 12.0;
  e.tolerance_pct = 5;
  EXPECT_EQ(judged(e, 12.5, 11.5).status, "pass");         // 4.2 %, -4.2 %
  EXPECT_EQ(judged(e, 12.7, std::nullopt).status, "fail"); // 5.8 %
  EXPECT_EQ(judged(e, std::nullopt, 11.3).status, "fail"); // -5.8 %
  EXPECT_NEAR(*judged(e, 12.6, std::nullopt).fe_error_pct, 5.0, 1e-12);
  EXPECT_EQ(judged(e, std::nullopt, std::nullopt).status, "fail"); // nothing computed
  e.check = CatalogueEntry::Check::at_most; // the value is itself a percentage
  e.published = 1.0;
  e.tolerance_pct = 0.5;
  EXPECT_EQ(judged(e, 0.49, std::nullopt).status, "pass");
  EXPECT_EQ(judged(e, 0.51, std::nullopt).status, "fail");
  e.expect = CatalogueEntry::Expect::finding;
  EXPECT_EQ(judged(e, 30.0, std::nullopt).status, "finding");
}

TEST(Validate, DiscretisationEstimateIsTheChangeFromTheCoarserMesh) {
  const CatalogueEntry e = entry_of_10();
  EntryResult r = fe_value(e, 10.0);
  r.eval.fe_coarse = 10.2;
  judge(r);
  ASSERT_TRUE(r.discretisation_pct.has_value());
  EXPECT_NEAR(*r.discretisation_pct, 2.0, 1e-12);
}

TEST(Validate, CatalogueErrorsNameTheEntry) {
  const std::string missing = write_catalogue(
      "missing_case.yaml", harwin_entry("ok.entry", 3.6e4) +
                               harwin_entry("bad.entry", 3.6e4, ", case: no/such/case.yaml"));
  try {
    read_catalogue(missing);
    FAIL() << "a missing case file must be an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.entry"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no/such/case.yaml"), std::string::npos) << e.what();
  }
  const std::string unknown = write_catalogue(
      "unknown_quantity.yaml",
      "- {id: q.entry, source: 003_x.txt, section: s, quantity: q, unit: N m, published: 1,\n"
      "   tolerance_pct: 5, tolerance_reason: r,\n"
      "   evaluate: {evaluator: compensator_sweep, quantity: torque_91,\n"
      "              case: " +
          test::example("3d/compensator_table42.yaml") + "}}\n");
  try {
    read_catalogue(unknown);
    FAIL() << "an unknown quantity must be an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("q.entry"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("torque_91"), std::string::npos) << e.what();
  }
}

TEST(Validate, BadInputExitsWithCode2NamingTheCulprit) {
  const auto out = std::filesystem::temp_directory_path() / "magfem_validate_bad";
  std::filesystem::remove_all(out);
  CliRun r = run_cli("--only no.such.entry --out " + out.string(), "only");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no.such.entry"), std::string::npos) << r.err;
  const std::string missing = write_catalogue(
      "cli_missing_case.yaml", harwin_entry("bad.case.entry", 3.6e4, ", case: missing.yaml"));
  r = run_cli("--catalogue " + missing + " --out " + out.string(), "missing");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("bad.case.entry"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out / "results.csv")) << "bad input writes nothing";
}

TEST(Validate, AFailingEntryExitsWith4AndDoesNotStopTheOthers) {
  // Published value off by far more than the 10 % tolerance: that entry fails, the next passes.
  const std::string cat = write_catalogue("one_fails.yaml", harwin_entry("wrong.value", 9e4) +
                                                                harwin_entry("right.value", 3.6e4));
  const auto out = std::filesystem::temp_directory_path() / "magfem_validate_fail";
  std::filesystem::remove_all(out);
  const CliRun r = run_cli("--catalogue " + cat + " --out " + out.string(), "fail");
  EXPECT_EQ(r.code, 4);
  EXPECT_NE(r.err.find("wrong.value"), std::string::npos) << r.err;
  const std::string csv = read_text(out / "results.csv");
  EXPECT_NE(csv.find("wrong.value"), std::string::npos);
  EXPECT_NE(csv.find(",fail,"), std::string::npos);
  EXPECT_NE(csv.find(",pass,"), std::string::npos) << "the second entry still ran";
}

// The quick tier on a subset that exercises every evaluator kind: analytic closed forms and
// 2D FE (Harwin), the charge interaction (compensator), the harmonic and charge models
// (32-magnet benchmark). Exit 0, the contract columns, no `fail`, all four reports.
TEST(Validate, QuickSubsetPassesWithTheContractColumns) {
  const auto out = std::filesystem::temp_directory_path() / "magfem_validate_quick";
  std::filesystem::remove_all(out);
  const CliRun r = run_cli("--tier quick --jobs 2 --out " + out.string() +
                               " --only harwin.fig4.fitted_current,harwin.t1.paper.max_ratio_8,"
                               "harwin.t1.paper.max_over_mean_2,harwin.t1.real_magnet.max_ratio_8,"
                               "thesis.c4.t42.zero_force_angle,thesis.c4.bonded_both.torque_90,"
                               "thesis.b32.harmonic_vs_charge.B_rho,thesis.b32.cost.unbounded,"
                               "thesis.c5.backiron_field.fe_segmented",
                           "quick");
  EXPECT_EQ(r.code, 0) << r.err;
  const std::string csv = read_text(out / "results.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), validation_csv_header);
  EXPECT_EQ(std::string(validation_csv_header),
            "id,source,section,quantity,unit,published,fe,analytic,tolerance_pct,fe_error_pct,"
            "analytic_error_pct,status,seconds,passes,unknowns,converged");
  EXPECT_EQ(csv.find(",fail,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",finding,"), std::string::npos);
  EXPECT_NE(csv.find(",skipped,"), std::string::npos);
  int rows = 0;
  for (char c : csv)
    rows += c == '\n';
  EXPECT_EQ(rows, 10); // header + 9 entries
  for (const char* f : {"results.json", "report.md", "report.html"})
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  const std::string json = read_text(out / "results.json");
  EXPECT_NE(json.find("\"magfem_version\""), std::string::npos);
  EXPECT_NE(json.find("\"git_commit\""), std::string::npos);
  EXPECT_NE(json.find("\"unknowns\""), std::string::npos) << "FE sizes recorded";
  const std::string html = read_text(out / "report.html");
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_EQ(html.find("http://"), html.find("http://www.w3.org/2000/svg"))
      << "no network resources";
}

// Thesis sec. 5.3.3 through `magfem validate` (validation/validate_eval_thesis_ch5.cpp): the peak
// mid-gap B_r with back-iron behind the magnets (+26 %) and behind magnets and coils (+80 %)
// by the charge model with imaging; both within paper_targets D's 3 points (measured +24.8 %
// and +82.1 %). Seconds.
TEST(Validate, ActuatorBackIronFieldIncrease) {
  const auto out = std::filesystem::temp_directory_path() / "magfem_validate_backiron";
  std::filesystem::remove_all(out);
  const CliRun r = run_cli("--out " + out.string() +
                               " --only thesis.c5.backiron_field.magnet,"
                               "thesis.c5.backiron_field.magnet_and_coil",
                           "backiron");
  EXPECT_EQ(r.code, 0) << r.err;
  const std::string csv = read_text(out / "results.csv");
  for (const char* row :
       {"thesis.c5.backiron_field.magnet,", "thesis.c5.backiron_field.magnet_and_coil,"}) {
    const auto at = csv.find(row);
    ASSERT_NE(at, std::string::npos) << csv;
    const std::string line = csv.substr(at, csv.find('\n', at) - at);
    EXPECT_NE(line.find(",pass,"), std::string::npos) << line;
  }
}

TEST(Validate, VoiceCoilTable1ByThePapersLineModel) {
  // Seed 002's Table 1 through `magfem validate` (validation/validate_eval_voicecoil.cpp): with the
  // paper's 2D line model and an integration range of 3 l, the a_i/a_o = 0.5 error at 1 um
  // (13.4 %) and eq. 6's sheet current of the thin coil (136.2 A/mm) pass, the thin coil's
  // 1.3 % at 1 um is a finding (no range gets below 2.17 %). Milliseconds per entry.
  const auto out = std::filesystem::temp_directory_path() / "magfem_validate_voicecoil";
  std::filesystem::remove_all(out);
  const CliRun r = run_cli("--out " + out.string() +
                               " --only voicecoil.table1.line_model.r05_1um,"
                               "voicecoil.table1.line_model.r09_1um,"
                               "voicecoil.table1.sheet_current.r09",
                           "voicecoil");
  EXPECT_EQ(r.code, 0) << r.err;
  const std::string csv = read_text(out / "results.csv");
  for (const char* row :
       {"voicecoil.table1.line_model.r05_1um,", "voicecoil.table1.line_model.r09_1um,",
        "voicecoil.table1.sheet_current.r09,"}) {
    const auto at = csv.find(row);
    ASSERT_NE(at, std::string::npos) << csv;
    const std::string line = csv.substr(at, csv.find('\n', at) - at);
    const bool finding = std::string(row).find("r09_1um") != std::string::npos;
    EXPECT_NE(line.find(finding ? ",finding," : ",pass,"), std::string::npos) << line;
  }
}

// --- FE entries solved to an accuracy (issue 29) ------------------------------------------

namespace {

// Harwin Table 1, the paper's model at the 2 mm gap (one 2D solve, about a second), with
// `fe` as the entry's evaluate.fe map.
std::string harwin_fe_entry(const std::string& id, const std::string& fe) {
  return "- id: " + id +
         "\n"
         "  source: 000_4b10982579af20cb.txt\n  section: Table 1\n  quantity: max / mean\n"
         "  unit: \"-\"\n  published: 1.93886\n  tolerance_pct: 10\n  tolerance_reason: test\n"
         "  evaluate: {evaluator: harwin_table1, quantity: max_over_mean, model: paper,\n"
         "             gap_mm: 2, magnet_radius_mm: 10,\n"
         "             case: " +
         test::source_dir() + "/validation/cases/harwin_paper_model.yaml,\n" +
         "             fe: " + fe + "}\n";
}

ValidationRun evaluated(const std::string& catalogue_file) {
  ValidateOptions o;
  o.catalogue = catalogue_file;
  o.jobs = 1;
  ValidationRun run = select_validation(o);
  evaluate_validation(run, nullptr);
  return run;
}

InputError catalogue_error(const std::string& name, const std::string& fe) {
  const std::string path = write_catalogue(name, harwin_fe_entry("bad.fe", fe));
  try {
    read_catalogue(path);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "evaluate.fe " << fe << " must be an InputError";
  return InputError("", 0, "", "");
}

} // namespace

// The entry asks for 1 % on the mid-gap probe from mesh scale 4: the loop's first pass has
// no estimate of the probe's error (one pass, nothing to compare), so it must take at least
// a second, and the entry's estimate is the loop's, not a change between scales.
// Planted: the accuracy ignored (fe_meshes() without the adapt spec) -> one fixed solve, no
// adaptive outcome -> fails.
TEST(Validate, AnFeEntryWithAnAccuracyRunsAdaptively) {
  const ValidationRun run = evaluated(
      write_catalogue("accuracy.yaml", harwin_fe_entry("adaptive.entry",
                                                       "{accuracy_pct: 1, quantity: probes.midgap, "
                                                       "start_scale: 4, reason: test}")));
  const EntryResult& r = run.results.at(0);
  ASSERT_EQ(r.status, "pass") << r.note;
  ASSERT_TRUE(r.eval.fe_adapt.has_value()) << "the accuracy was ignored";
  EXPECT_GT(r.eval.fe_adapt->passes, 1);
  EXPECT_TRUE(r.eval.fe_adapt->converged);
  EXPECT_DOUBLE_EQ(r.eval.fe_adapt->accuracy_pct, 1.0);
  ASSERT_TRUE(r.discretisation_pct.has_value());
  EXPECT_EQ(*r.discretisation_pct, r.eval.fe_adapt->estimate_pct);
  EXPECT_LE(*r.discretisation_pct, 1.0);
  EXPECT_GT(r.eval.fe_unknowns.value_or(0), 0);
  // The FE value of the paper's model against its Fourier series (mu_r 1e5 iron for the
  // series' infinitely permeable one, a 0.03 mm sheet for its surface current): measured
  // 0.11 % apart; 1 % is the model difference's bound, far below the 10 % tolerance.
  ASSERT_TRUE(r.fe && r.analytic);
  EXPECT_NEAR(*r.fe / *r.analytic, 1.0, 0.01);
}

// The paper's model solved by FE against its Fourier series (analytic/closed_forms), two
// independent methods: the FE sheet's non-magnetic thickness t widens every gap by t, so to
// first order B(g) ~ 1 / (g + t) and the ratio B(8 mm) / B(2 mm) exceeds the series' by
// t (1/2 - 1/8) / mm = 1.125 % at t = 0.03 mm (measured 1.07 %). 0.25 points allow the
// second-order t^2 / g^2 (0.02 %), the mu_r 1e5 iron's own reluctance (~0.02 %) and the FE
// error (estimated <= 0.1 % at 0.2 %). Planted, each fails: the iron at mu_r 1000 (the
// file's earlier value: 2.6 %), the sheet 0.3 mm thick (10.8 %), the series' MMF harmonics
// 1/k instead of 1/k^2 (a square wave for the triangle: FE / series 1.34).
TEST(Validate, HarwinPaperModelFeMatchesTheSeriesUpToTheSheetThickness) {
  const std::string entry =
      std::string(
          "- id: harwin.fe.vs.series\n"
          "  source: 000_4b10982579af20cb.txt\n  section: Table 1\n  quantity: ratio\n"
          "  unit: \"-\"\n  published: 0.23256\n  tolerance_pct: 10\n  tolerance_reason: test\n"
          "  evaluate: {evaluator: harwin_table1, quantity: max_ratio, model: paper,\n"
          "             gap_mm: 8, magnet_radius_mm: 10,\n"
          "             case: ") +
      test::source_dir() + "/validation/cases/harwin_paper_model.yaml,\n" +
      "             fe: {accuracy_pct: 0.2, quantity: probes.midgap, start_scale: 4, reason: "
      "test}}\n";
  const ValidationRun run = evaluated(write_catalogue("fe_vs_series.yaml", entry));
  const EntryResult& r = run.results.at(0);
  ASSERT_TRUE(r.fe && r.analytic) << r.note;
  // The sheet's thickness from the case itself (its current-carrying sectors), as the
  // evaluator reads it: a thinner sheet written there moves both the FE and the prediction.
  const CaseSpec model =
      read_case(std::string(test::source_dir()) + "/validation/cases/harwin_paper_model.yaml");
  double t_mm = 0;
  for (std::size_t i = 0; i < model.regions.size(); ++i)
    if (const auto* s = std::get_if<AnnularSector>(&model.geometry2d.parts[i].shape);
        s && model.regions[i].carries_current())
      t_mm = std::max(t_mm, 1e3 * (s->r_outer - s->r_inner));
  ASSERT_GT(t_mm, 0) << "no current sheet found in the case";
  const double predicted_pct = 100 * t_mm * (1.0 / 2 - 1.0 / 8);
  EXPECT_NEAR(100 * (*r.fe / *r.analytic - 1), predicted_pct, 0.25)
      << "FE " << *r.fe << ", series " << *r.analytic;
  // The page states the expected difference (printed to 3 significant digits): the number
  // is read back, not matched as text, so a value rounding at its last digit still compares.
  const std::string label = "t (1/2 mm - 1/g) = ";
  const std::size_t at = r.eval.method.find(label);
  ASSERT_NE(at, std::string::npos) << "the page states the expected difference: " << r.eval.method;
  const double stated_pct = std::stod(r.eval.method.substr(at + label.size()));
  EXPECT_NEAR(stated_pct, predicted_pct, 0.005 * predicted_pct) << r.eval.method;
}

// A loop stopped by a limit (one pass allowed: no estimate yet) is not a silent pass: the
// entry fails with a note saying so, results.csv says converged = no, the page says "not
// converged", exit code 4. Planted: converged forced true in adapt_outcome -> passes -> fails.
TEST(Validate, ALimitStoppedFeEntryIsReportedNotConverged) {
  const std::string cat = write_catalogue(
      "limit.yaml",
      harwin_fe_entry("limited.entry", "{accuracy_pct: 1, quantity: probes.midgap, "
                                       "start_scale: 4, max_passes: 1, reason: test}"));
  const auto out = std::filesystem::temp_directory_path() / "magfem_validate_limit";
  std::filesystem::remove_all(out);
  const CliRun r = run_cli("--catalogue " + cat + " --out " + out.string(), "limit");
  EXPECT_EQ(r.code, 4) << r.err;
  EXPECT_NE(r.err.find("FE not converged"), std::string::npos) << "the console says why: " << r.err;
  const std::string csv = read_text(out / "results.csv");
  const std::string row = csv.substr(csv.find("limited.entry"));
  EXPECT_NE(row.find(",fail,"), std::string::npos) << row;
  EXPECT_NE(row.find(",1,"), std::string::npos) << "one pass: " << row;
  EXPECT_EQ(row.substr(row.rfind(',') + 1), "no\n") << row;
  const std::string json = read_text(out / "results.json");
  EXPECT_NE(json.find("FE not converged"), std::string::npos);
  EXPECT_NE(json.find("max_passes (1) reached"), std::string::npos);
  EXPECT_NE(read_text(out / "report.html").find("not converged"), std::string::npos);
}

// judge() alone: a value inside its tolerance whose adaptive solve stopped at a limit fails;
// a finding keeps its status but carries the note.
TEST(Validate, JudgeFailsAnUnconvergedFeValue) {
  CatalogueEntry e = entry_of_10();
  EntryResult r = fe_value(e, 10.1);
  r.eval.fe_adapt = FeAdaptOutcome{0.5, 10, false, "max_passes (10) reached", 0.8};
  judge(r);
  EXPECT_EQ(r.status, "fail");
  EXPECT_NE(r.note.find("not converged"), std::string::npos) << r.note;
  EXPECT_DOUBLE_EQ(*r.discretisation_pct, 0.8); // the loop's estimate, not a change
  r.eval.fe_adapt->converged = true;
  r.note.clear();
  judge(r);
  EXPECT_EQ(r.status, "pass");
  e.expect = CatalogueEntry::Expect::finding;
  r.eval.fe_adapt->converged = false;
  judge(r);
  EXPECT_EQ(r.status, "finding");
  EXPECT_NE(r.note.find("not converged"), std::string::npos) << r.note;
}

// results.csv keeps its contract columns in their order and appends passes, unknowns and
// converged, whose cells sit under their names. Planted: the new columns put before
// `seconds` -> fails.
TEST(Validate, ResultsCsvAppendsTheAdaptiveColumns) {
  const std::string old_columns = "id,source,section,quantity,unit,published,fe,analytic,"
                                  "tolerance_pct,fe_error_pct,analytic_error_pct,status,seconds";
  EXPECT_EQ(std::string(validation_csv_header), old_columns + ",passes,unknowns,converged");
  const CatalogueEntry e = entry_of_10();
  ValidationRun run;
  run.results = {fe_value(e, 10.1), fe_value(e, 10.1)};
  EntryResult& adaptive = run.results[0];
  adaptive.eval.fe_adapt = FeAdaptOutcome{0.5, 3, false, "max_unknowns", 0.8};
  adaptive.eval.fe_unknowns = 123456;
  adaptive.seconds = 1.5;
  judge(adaptive);
  EntryResult& fixed = run.results[1];
  fixed.eval.fe_unknowns = 789;
  judge(fixed);
  std::stringstream csv(validation_csv(run));
  std::string header, row1, row2;
  std::getline(csv, header), std::getline(csv, row1), std::getline(csv, row2);
  EXPECT_EQ(row1.substr(row1.find(",fail,")), ",fail,1.50,3,123456,no");
  EXPECT_EQ(row2.substr(row2.find(",pass,")), ",pass,0.00,,789,") << "fixed scales: no passes";
}

// Bad accuracies in the catalogue: an InputError naming the catalogue file, the line and
// evaluate.fe's field. Planted: the (0, 100) check dropped -> the 0 and 100 cases pass -> fail.
TEST(Validate, BadFeAccuracyNamesFileLineAndField) {
  const struct {
    const char* name;
    std::string fe, field, says;
  } cases[] = {
      {"zero.yaml", "{accuracy_pct: 0, quantity: probes.midgap, reason: r}", "accuracy_pct",
       "> 0 and < 100"},
      {"hundred.yaml", "{accuracy_pct: {quick: 1, full: 100}, quantity: probes.midgap, reason: r}",
       "full", "> 0 and < 100"},
      {"quantity.yaml", "{accuracy_pct: 1, quantity: probes.nowhere, reason: r}", "quantity",
       "no probe named 'nowhere'"},
      {"syntax.yaml", "{accuracy_pct: 1, quantity: torque, reason: r}", "quantity",
       "unknown quantity 'torque'"},
      {"both.yaml", "{accuracy_pct: 1, quick: [2, 1], quantity: energy, reason: r}", "quick",
       "not both"},
      {"no_reason.yaml", "{quick: [2, 1]}", "fe", "needs a reason"},
  };
  for (const auto& c : cases) {
    const InputError e = catalogue_error(c.name, c.fe);
    EXPECT_NE(e.file().find(c.name), std::string::npos) << c.name << ": " << e.what();
    EXPECT_GT(e.line(), 1) << c.name << ": " << e.what();
    EXPECT_NE(e.field().find(c.field), std::string::npos) << c.name << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.fe"), std::string::npos) << e.what();
  }
}
