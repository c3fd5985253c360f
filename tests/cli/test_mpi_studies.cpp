// `mpirun -n 2|3 magfem study` and `validate` (designs and catalogue entries dealt to the
// processes, rank 0 writing) against the
// serial run with --jobs 1: the same study.csv byte for byte (and plot), the same summary.json
// but for the times, the same exit code (3 when designs fail) from every process, for an
// analytic grid (harmonic form, milliseconds a design) and a coarse FE one; --resume under
// mpirun takes the checkpoint's designs and evaluates only the others; a bad option or group
// ends every process with exit 2 and nothing written, never a hang; optimize is refused with
// its reason. validate likewise: results.csv, results.json and the reports the serial run's
// but for the times; exit 4 from every process when an entry fails; --resume across
// processes. actuator --verify: its FE verification solves dealt, the serial outputs but the
// times; without --verify refused.
//
// Byte comparison is right here (not a tolerance): each design is the same deterministic
// computation whichever process runs it (a design's BLAS on one thread, the position's
// element loops reduced in a fixed order), and its doubles travel as JSON's shortest
// round-trip text, so any difference is a row lost, doubled, misplaced or re-rounded.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/case_helpers.hpp"
#include "tests/cli/mpi_helpers.hpp"
#include "tests/run_cli.hpp"
#include "tests/validation_csv.hpp"

namespace fs = std::filesystem;
using magfem::test::CliOutcome;
using magfem::test::fresh_dir;
using magfem::test::read_json;
using magfem::test::run_mpi;
using magfem::test::text_of;

namespace {

class MpiStudies : public ::testing::Test {
protected:
  void SetUp() override {
    if (magfem::test::mpirun_path().empty())
      GTEST_SKIP() << "mpirun not found (Debian: mpi-default-bin, scripts/install_deps.sh)";
  }
};

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

// `text` written as NAME in the test's output folder (beside the runs' folders).
fs::path case_beside(const fs::path& run_dir, const std::string& name, const std::string& text) {
  fs::create_directories(run_dir.parent_path());
  const fs::path file = run_dir.parent_path() / name;
  std::ofstream(file) << text;
  return file;
}

// summary.json without what a rerun does not reproduce: the designs' summed wall-clock time.
nlohmann::json without_times(const fs::path& summary) {
  auto j = read_json(summary);
  j.erase("seconds");
  return j;
}

// The compensator's radii (examples/3d/compensator_study.yaml), 12 designs of which two
// (R_out 44 and 48 with R_in 50) cannot be built: rows that fail on whichever process gets
// them, so the exit code is 3 and summary.json lists them.
std::string compensator_grid(const std::string& r_out = "44:4:56",
                             const std::string& r_in = "30,35,50") {
  return "study " + magfem::test::example("3d/compensator_study.yaml") + " --param R_out=" + r_out +
         " --param R_in=" + r_in +
         " --objective peak_torque --objective torque_at:90 --rotate outer --axis y "
         "--angles 0:30:180 --jobs 1";
}

void expect_same_outputs(const fs::path& serial, const fs::path& dir, int n) {
  EXPECT_EQ(text_of(dir / "study.csv"), text_of(serial / "study.csv")) << n << " processes";
  EXPECT_EQ(without_times(dir / "summary.json"), without_times(serial / "summary.json"))
      << n << " processes";
  if (fs::exists(serial / "study.png")) { // gnuplot installed
    EXPECT_TRUE(text_of(dir / "study.png") == text_of(serial / "study.png"))
        << "study.png differs on " << n << " processes";
  }
  EXPECT_FALSE(fs::exists(dir / ".magfem-checkpoint.jsonl"));
}

// Would fail on: designs written in arrival order (rank order leaking into study.csv), a
// design lost or evaluated on two processes (a missing or doubled line), a failed design of
// another process not reported (designs/failed_designs/failures, exit 0 instead of 3).
TEST_F(MpiStudies, AnalyticStudyOnTwoAndThreeProcessesWritesTheSerialOutputs) {
  const fs::path serial = fresh_dir("study_serial");
  const CliOutcome s =
      magfem::test::run_cli(compensator_grid() + " --quiet --out " + serial.string());
  ASSERT_EQ(s.status, 3) << s.out;
  ASSERT_EQ(read_json(serial / "summary.json")["failed_designs"], 2);
  for (const int n : {2, 3}) {
    const fs::path dir = fresh_dir("study_" + std::to_string(n) + "_ranks");
    const CliOutcome m = run_mpi(n, compensator_grid() + " --out " + dir.string());
    EXPECT_EQ(m.status, 3) << m.out;
    expect_same_outputs(serial, dir, n);
    EXPECT_EQ(count(m.out, "wrote    "), 1u) << m.out;
    EXPECT_EQ(count(m.out, "2 of 12 designs failed"), 1u) << m.out;
    EXPECT_EQ(count(m.out, "study on " + std::to_string(n) + " processes"), 1u) << m.out;
  }
  fs::remove_all(serial.parent_path());
}

// Two hemispherical magnets (the compensator's topology at a third of its size) meshed
// coarsely: an FE design takes a few seconds, its torque from the Maxwell stress sphere.
std::string small_compensator() {
  return text_of(fs::path(magfem::test::source_dir()) / "tests/cli/small_compensator.yaml");
}

// The FE path: meshing and solving inside the dealt design, unknowns and torques through the
// design codec (a re-rounded torque changes study.csv's last digits).
TEST_F(MpiStudies, CoarseFeStudyOnTwoProcessesWritesTheSerialOutputs) {
  const fs::path serial = fresh_dir("fe_study_serial"), dir = fresh_dir("fe_study_2_ranks");
  const fs::path case_file = case_beside(serial, "small_compensator.yaml", small_compensator());
  const std::string study = "study " + case_file.string() +
                            " --param R_out=26,30 --objective torque_at:90 --rotate outer "
                            "--axis y --fe --jobs 1 --quiet";
  const CliOutcome s = magfem::test::run_cli(study + " --out " + serial.string());
  ASSERT_EQ(s.status, 0) << s.out;
  const CliOutcome m = run_mpi(2, study + " --out " + dir.string());
  ASSERT_EQ(m.status, 0) << m.out;
  expect_same_outputs(serial, dir, 2);
  EXPECT_EQ(read_json(dir / "summary.json")["method"], "maxwell_stress_sphere");
  fs::remove_all(serial.parent_path());
}

// A checkpoint holding 4 of the 8 designs (a serial run's, cut down), one of them with a
// planted torque 1234.5 N m, then --resume under mpirun: the planted value appears in
// study.csv (the checkpoint was used and that design not evaluated again) and every other
// line is the serial run's (the missing designs were evaluated, each once, in place).
TEST_F(MpiStudies, ResumedStudyUnderMpirunEvaluatesOnlyTheMissingDesigns) {
  const std::string grid = compensator_grid("44:4:56", "30,35");
  const fs::path serial = fresh_dir("resume_study_serial"), dir = fresh_dir("resume_study_mpi");
  ASSERT_EQ(magfem::test::run_cli(grid + " --quiet --out " + serial.string()).status, 0);
  // A directory where study.csv goes: the run cannot commit its outputs and keeps its
  // checkpoint of all eight designs.
  fs::create_directories(dir / "study.csv" / "blocker");
  ASSERT_EQ(magfem::test::run_cli(grid + " --quiet --out " + dir.string()).status, 1);
  fs::remove_all(dir / "study.csv");
  const fs::path checkpoint = dir / ".magfem-checkpoint.jsonl";
  std::stringstream lines(text_of(checkpoint));
  std::string line, kept;
  std::getline(lines, line); // the identity
  kept = line + "\n";
  for (int i = 0; std::getline(lines, line) && i < 8; ++i) {
    auto entry = nlohmann::json::parse(line);
    if (entry["key"] == "44,30")
      entry["value"]["objectives"][0] = 1234.5;
    if (i % 2 == 0) // designs 44/30, 48/30, 52/30, 56/30 kept
      kept += entry.dump() + "\n";
  }
  std::ofstream(checkpoint) << kept;

  const CliOutcome m = run_mpi(2, grid + " --resume --out " + dir.string());
  ASSERT_EQ(m.status, 0) << m.out;
  EXPECT_NE(m.out.find("--resume: 4 finished designs"), std::string::npos) << m.out;
  std::string expected = text_of(serial / "study.csv");
  const auto at = expected.find("\n44,30,") + 7;
  expected.replace(at, expected.find(',', at) - at, "1234.5");
  EXPECT_EQ(text_of(dir / "study.csv"), expected);
  EXPECT_FALSE(fs::exists(checkpoint));
  fs::remove_all(serial.parent_path());
}

// Every process reads the same options, so each fails alike: exit 2 from all through
// MPI_Abort within the timeout, nothing written. An unknown group is found only when a
// design is evaluated, on whichever process has it: it ends the run as bad input, not as
// twelve failed designs.
TEST_F(MpiStudies, BadStudyInputEndsEveryProcessWithExitTwo) {
  const fs::path dir = fresh_dir("study_bad");
  const CliOutcome option = run_mpi(2, compensator_grid() + " --bogus --out " + dir.string());
  EXPECT_EQ(option.status, 2) << option.out;
  EXPECT_NE(option.out.find("--bogus"), std::string::npos) << option.out;
  std::string grid = compensator_grid();
  grid.replace(grid.find("--rotate outer"), 14, "--rotate nosuch");
  const CliOutcome group = run_mpi(3, grid + " --out " + dir.string());
  EXPECT_EQ(group.status, 2) << group.out;
  EXPECT_NE(group.out.find("nosuch"), std::string::npos) << group.out;
  EXPECT_FALSE(fs::exists(dir / "study.csv"));
  EXPECT_FALSE(fs::exists(dir / "summary.json"));
  fs::remove_all(dir.parent_path());
}

// optimize chooses each design from the ones before: nothing to deal. Refused before its
// options are read, on every process, with the reason.
TEST_F(MpiStudies, OptimizeIsRefusedUnderMpirunWithItsReason) {
  const CliOutcome o = run_mpi(2, "optimize " + magfem::test::example("3d/compensator_study.yaml"));
  EXPECT_EQ(o.status, 2) << o.out;
  EXPECT_NE(o.out.find("sequential"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("without mpirun"), std::string::npos) << o.out;
}

// ---- validate ------------------------------------------------------------------------------

// The Harwin entries (seed 000: analytic fits and coarse 2D FE of the paper's model, ~4 s in
// all), with --jobs 1 as the serial reference.
std::string harwin_entries() {
  return "validate --source 000 --jobs 1";
}

// The outputs without what a rerun does not reproduce: every time (each entry's seconds, a
// CSV column; the JSON `seconds` of the entries and of the solves in their details; the
// run's wall time in results.json and the reports' "in N s"; the details the HTML report
// shows).
std::string csv_without_seconds(const fs::path& csv) {
  return magfem::test::validation_csv_without_seconds(text_of(csv));
}
void erase_seconds(nlohmann::json& j) {
  if (j.is_object()) {
    j.erase("seconds");
    j.erase("wall_seconds");
  }
  if (j.is_structured())
    for (auto& v : j)
      erase_seconds(v);
}
nlohmann::json results_without_times(const fs::path& json) {
  auto j = read_json(json);
  erase_seconds(j);
  return j;
}
std::string report_without_times(const fs::path& report) {
  const std::string text =
      std::regex_replace(text_of(report), std::regex("in [0-9.]+ s on"), "in T s on");
  return std::regex_replace(text, std::regex("seconds&quot;: [-0-9.e]+"), "seconds&quot;: T");
}

void expect_same_validation(const fs::path& serial, const fs::path& dir, int n) {
  EXPECT_EQ(csv_without_seconds(dir / "results.csv"), csv_without_seconds(serial / "results.csv"))
      << n << " processes";
  EXPECT_EQ(results_without_times(dir / "results.json"),
            results_without_times(serial / "results.json"))
      << n << " processes";
  EXPECT_EQ(report_without_times(dir / "report.md"), report_without_times(serial / "report.md"));
  EXPECT_EQ(report_without_times(dir / "report.html"),
            report_without_times(serial / "report.html"));
  EXPECT_FALSE(fs::exists(dir / ".magfem-checkpoint.jsonl"));
}

// Would fail on: entries reported in arrival order, an entry lost or evaluated twice, a value
// or note re-rounded or dropped on its way to rank 0 (entries of other processes have no
// shared cache with rank 0's, so they compute their own), the report written by two
// processes.
TEST_F(MpiStudies, ValidateOnTwoAndThreeProcessesWritesTheSerialOutputs) {
  const fs::path serial = fresh_dir("validate_serial");
  const CliOutcome s = magfem::test::run_cli(harwin_entries() + " --out " + serial.string());
  ASSERT_EQ(s.status, 0) << s.out;
  for (const int n : {2, 3}) {
    const fs::path dir = fresh_dir("validate_" + std::to_string(n) + "_ranks");
    const CliOutcome m = run_mpi(n, harwin_entries() + " --out " + dir.string());
    ASSERT_EQ(m.status, 0) << m.out;
    expect_same_validation(serial, dir, n);
    EXPECT_EQ(count(m.out, "wrote    "), 1u) << m.out;
    EXPECT_EQ(count(m.out, "validate on " + std::to_string(n) + " processes"), 1u) << m.out;
  }
  fs::remove_all(serial.parent_path());
}

// The catalogue with every case path absolute (so that a copy elsewhere reads the same
// cases) and the entry `id`'s published value replaced by `published`.
fs::path catalogue_with(const fs::path& dir, const std::string& id, const std::string& published) {
  const fs::path source = magfem::test::source_dir();
  std::string text = text_of(source / "validation" / "catalogue.yaml");
  text = std::regex_replace(text, std::regex("case: cases/"),
                            "case: " + (source / "validation" / "cases").string() + "/");
  text = std::regex_replace(text, std::regex("case: \\.\\./examples/"),
                            "case: " + (source / "examples").string() + "/");
  const auto at = text.find("published:", text.find("- id: " + id + "\n"));
  text.replace(at, text.find('\n', at) - at, "published: " + published);
  fs::create_directories(dir);
  const fs::path file = dir / "catalogue.yaml";
  std::ofstream(file) << text;
  return file;
}

// An entry that fails its check on whichever process evaluates it: exit 4 from every
// process, its id named once, the outputs still written (all entries, the failure among
// them), as serially. Would fail if rank 0 ignored another process's failed entry.
TEST_F(MpiStudies, ValidateWithAFailingEntryExitsFourOnEveryProcess) {
  const fs::path dir = fresh_dir("validate_failing");
  const fs::path catalogue = catalogue_with(dir, "harwin.t1.paper.max_ratio_8", "0.5");
  const std::string run = harwin_entries() + " --catalogue " + catalogue.string();
  const CliOutcome s = magfem::test::run_cli(run + " --out " + (dir / "serial").string());
  ASSERT_EQ(s.status, 4) << s.out;
  const CliOutcome m = run_mpi(3, run + " --out " + (dir / "mpi").string());
  EXPECT_EQ(m.status, 4) << m.out;
  // Once, from rank 0. mpirun forwards a process's stdout and stderr separately, so the
  // "wrote" line can land inside the failure line (CI saw "validation failed:<wrote ...>
  // harwin..."): the prefix and the id are counted apart.
  EXPECT_EQ(count(m.out, "validation failed:"), 1u) << m.out;
  EXPECT_NE(m.out.find("harwin.t1.paper.max_ratio_8"), std::string::npos) << m.out;
  expect_same_validation(dir / "serial", dir / "mpi", 3);
  fs::remove_all(dir.parent_path());
}

// A serial run's checkpoint (its outputs blocked), cut to half the entries, one of them with
// a planted analytic value 4321, then --resume under mpirun: the planted value is in
// results.csv (taken from the checkpoint, not evaluated again), the other entries are the
// serial run's.
TEST_F(MpiStudies, ResumedValidateUnderMpirunEvaluatesOnlyTheMissingEntries) {
  const fs::path serial = fresh_dir("resume_validate_serial"), dir = fresh_dir("resume_validate");
  ASSERT_EQ(magfem::test::run_cli(harwin_entries() + " --out " + serial.string()).status, 0);
  fs::create_directories(dir / "results.csv" / "blocker");
  ASSERT_EQ(magfem::test::run_cli(harwin_entries() + " --out " + dir.string()).status, 1);
  fs::remove_all(dir / "results.csv");
  const fs::path checkpoint = dir / ".magfem-checkpoint.jsonl";
  std::stringstream lines(text_of(checkpoint));
  std::string line, kept, planted;
  std::getline(lines, line);
  kept = line + "\n";
  for (int i = 0; std::getline(lines, line); ++i) {
    auto entry = nlohmann::json::parse(line);
    if (i % 2)
      continue;
    if (planted.empty() && entry["value"]["analytic"].is_number()) {
      planted = entry["key"];
      entry["value"]["analytic"] = 4321.0;
    }
    kept += entry.dump() + "\n";
  }
  ASSERT_FALSE(planted.empty());
  std::ofstream(checkpoint) << kept;

  const CliOutcome m = run_mpi(2, harwin_entries() + " --resume --out " + dir.string());
  ASSERT_EQ(m.status, 0) << m.out;
  const auto results = read_json(dir / "results.json");
  const auto reference = read_json(serial / "results.json");
  ASSERT_EQ(results["entries"].size(), reference["entries"].size());
  for (std::size_t i = 0; i < results["entries"].size(); ++i) {
    auto e = results["entries"][i], r = reference["entries"][i];
    if (e["id"] == planted) {
      EXPECT_EQ(e["analytic"], 4321.0) << planted << " evaluated again";
      continue;
    }
    erase_seconds(e), erase_seconds(r);
    EXPECT_EQ(e, r);
  }
  EXPECT_FALSE(fs::exists(checkpoint));
  fs::remove_all(serial.parent_path());
}

// ---- actuator --verify -------------------------------------------------------------------

// The suite's small actuator (tests/case_helpers.hpp), constants by the charge model, three
// orientations: three FE verification solves (first, middle, last orientation, ~2 s each at
// order 1), one per process at -n 3. The torques travel through the verification codec:
// rank order leaking or a row lost changes summary.json's `verification`.
TEST_F(MpiStudies, ActuatorVerifyOnThreeProcessesWritesTheSerialOutputs) {
  const fs::path serial = fresh_dir("actuator_serial"), dir = fresh_dir("actuator_3_ranks");
  const fs::path case_file =
      case_beside(serial, "small_actuator.yaml", magfem::test::small_actuator_case);
  const std::string run = "actuator " + case_file.string() +
                          " --rotor rotor --orientations rx=0,ry=0:10:20 --torque 0,0,0.001 "
                          "--analytic --verify --order 1 --quiet";
  const CliOutcome s = magfem::test::run_cli(run + " --out " + serial.string());
  ASSERT_EQ(s.status, 0) << s.out;
  const CliOutcome m = run_mpi(3, run + " --out " + dir.string());
  ASSERT_EQ(m.status, 0) << m.out;
  for (const char* file : {"commutation.csv", "torque_constants.csv"})
    EXPECT_EQ(text_of(dir / file), text_of(serial / file)) << file;
  auto without_seconds = [](const fs::path& summary) {
    auto j = read_json(summary);
    j.erase("seconds");
    j.erase("torque_constants_seconds");
    return j;
  };
  const auto summary = without_seconds(dir / "summary.json");
  EXPECT_EQ(summary, without_seconds(serial / "summary.json"));
  EXPECT_EQ(summary["verification"].size(), 3u);
  EXPECT_EQ(count(m.out, "verify   T_d at"), 3u) << m.out;
  EXPECT_EQ(count(m.out, "actuator --verify on 3 processes"), 1u) << m.out;
  fs::remove_all(serial.parent_path());
}

// Without --verify there is nothing to deal: refused on every process, exit 2.
TEST_F(MpiStudies, ActuatorWithoutVerifyIsRefusedUnderMpirun) {
  const CliOutcome o =
      run_mpi(2, "actuator " + magfem::test::example("3d/spherical_actuator_design.yaml") +
                     " --rotor rotor --orientations rx=0 --analytic");
  EXPECT_EQ(o.status, 2) << o.out;
  EXPECT_NE(o.out.find("only with --verify"), std::string::npos) << o.out;
}

} // namespace
