// Ctrl-C and kill during a run (core/interrupt.hpp): the binary exits with the shell's code
// for the signal (130 for SIGINT, 143 for SIGTERM), says so, and leaves no outputs: no
// sweep.csv or summary.json, no staging folder; only the sweep's checkpoint, from which
// --resume continues (pipeline/run_checkpoint.hpp; sweep, validate and study). The signal goes to
// an axisymmetric sweep of remeshed positions once some are reported, while meshing and
// solving are under way, and to a study once some designs are in its checkpoint.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "pipeline/run_checkpoint.hpp"
#include "tests/case_helpers.hpp"
#include "tests/test_paths.hpp"
#include "tests/validation_csv.hpp"

namespace fs = std::filesystem;

namespace {

struct Outcome {
  int exit_code = -1;
  std::string stderr_text;
};

std::string text_of(const fs::path& p) {
  std::stringstream s;
  s << std::ifstream(p).rdbuf();
  return s.str();
}

// Starts magfem with `args` (after the binary), stdout to /dev/null and stderr to
// `<out>.stderr`; returns the child's pid.
pid_t spawn_magfem(const std::vector<std::string>& args, const fs::path& out) {
  const fs::path err = out.string() + ".stderr";
  fs::remove(err);
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 2);
    const int null = ::open("/dev/null", O_WRONLY);
    dup2(null, 1);
    std::vector<const char*> argv = {magfem::test::magfem_binary()};
    for (const auto& a : args)
      argv.push_back(a.c_str());
    argv.push_back(nullptr);
    execv(magfem::test::magfem_binary(), const_cast<char* const*>(argv.data()));
    _exit(127);
  }
  return pid;
}

// Starts `magfem sweep` of the voice-coil magnet over `positions` into `out`; `mesh_scale`
// coarsens the meshes (seconds matter in the resume test).
pid_t start_sweep(const std::string& positions, const fs::path& out, bool resume,
                  const std::string& mesh_scale = "1") {
  std::vector<std::string> args = {
      "sweep",        magfem::test::example("axi/voice_coil_magnet.yaml"),
      "--move",       "coil",
      "--axis",       "z",
      "--positions",  positions,
      "--jobs",       "1",
      "--out",        out.string(),
      "--mesh-scale", mesh_scale};
  if (resume)
    args.push_back("--resume");
  return spawn_magfem(args, out);
}

Outcome finish(pid_t pid, const fs::path& out) {
  int status = 0;
  waitpid(pid, &status, 0);
  Outcome o;
  if (WIFEXITED(status))
    o.exit_code = WEXITSTATUS(status);
  o.stderr_text = text_of(out.string() + ".stderr");
  return o;
}

// Sends `sig` once the sweep has reported `progress` (e.g. "position 1/") on stderr: the
// handler is installed then (a signal before main() would kill the process instead).
Outcome interrupt_sweep(int sig, const fs::path& out, const std::string& positions,
                        const std::string& progress, const std::string& mesh_scale = "1") {
  fs::remove_all(out);
  const pid_t pid = start_sweep(positions, out, false, mesh_scale);
  const auto t0 = std::chrono::steady_clock::now();
  while (text_of(out.string() + ".stderr").find(progress) == std::string::npos &&
         std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(pid, sig);
  return finish(pid, out);
}

// Nothing but the checkpoint (not an output: a hidden file --resume reads).
void expect_nothing_written(const fs::path& out) {
  if (!fs::exists(out))
    return;
  for (const auto& f : fs::directory_iterator(out))
    if (f.path().filename() != magfem::RunCheckpoint::file_name)
      ADD_FAILURE() << "left behind: " << f.path();
}

fs::path test_dir(const std::string& name) {
  const fs::path out = fs::temp_directory_path() / "magfem_tests" / name;
  fs::create_directories(out.parent_path());
  return out;
}

} // namespace

TEST(Interrupt, SigintDuringASweepExits130AndLeavesNoOutputs) {
  const fs::path out = test_dir("interrupt_int");
  const auto o = interrupt_sweep(SIGINT, out, "0:0.2:12", "position 1/");
  EXPECT_EQ(o.exit_code, 130) << o.stderr_text;
  EXPECT_NE(o.stderr_text.find("interrupted by SIGINT"), std::string::npos) << o.stderr_text;
  expect_nothing_written(out);
}

TEST(Interrupt, SigtermDuringASweepExits143AndLeavesNoOutputs) {
  const fs::path out = test_dir("interrupt_term");
  const auto o = interrupt_sweep(SIGTERM, out, "0:0.2:12", "position 1/");
  EXPECT_EQ(o.exit_code, 143) << o.stderr_text;
  EXPECT_NE(o.stderr_text.find("interrupted by SIGTERM"), std::string::npos) << o.stderr_text;
  expect_nothing_written(out);
}

// The promise: --resume after Ctrl-C gives the sweep.csv of an uninterrupted run,
// byte for byte (restored positions are the computed doubles, 17 digits in the checkpoint;
// a position solved again is deterministic). Would fail if restored rows were re-rounded,
// misplaced (keyed by index instead of position), dropped, or all recomputed.
TEST(Interrupt, ResumedSweepWritesTheSameCsvAsAnUninterruptedRun) {
  // 21 positions: with 6 the sweep (0.1-0.2 s a position at this scale) once finished them
  // all in the 300 ms between "position 2/" and the signal.
  const std::string positions = "0:0.5:10", scale = "2";
  const fs::path whole = test_dir("resume_whole"), resumed = test_dir("resume_resumed");
  fs::remove_all(whole);
  const auto w = finish(start_sweep(positions, whole, false, scale), whole);
  ASSERT_EQ(w.exit_code, 0) << w.stderr_text;

  const auto i = interrupt_sweep(SIGINT, resumed, positions, "position 2/", scale);
  ASSERT_EQ(i.exit_code, 130) << i.stderr_text;
  expect_nothing_written(resumed);
  const fs::path checkpoint = resumed / magfem::RunCheckpoint::file_name;
  ASSERT_TRUE(fs::exists(checkpoint));
  std::stringstream lines(text_of(checkpoint));
  int n_lines = 0;
  for (std::string line; std::getline(lines, line);)
    ++n_lines;
  EXPECT_GE(n_lines - 1, 2) << "positions 1-2 were reported done before the signal";
  EXPECT_LT(n_lines - 1, 21);

  const auto r = finish(start_sweep(positions, resumed, true, scale), resumed);
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("finished positions from the checkpoint"), std::string::npos)
      << r.stderr_text;
  EXPECT_EQ(text_of(resumed / "sweep.csv"), text_of(whole / "sweep.csv"));
  EXPECT_FALSE(fs::exists(checkpoint)) << "the checkpoint goes once the outputs are written";
}

// A checkpoint of another run is refused rather than mixed in.
TEST(Interrupt, ResumeRefusesTheCheckpointOfADifferentRun) {
  const fs::path out = test_dir("resume_other");
  fs::remove_all(out);
  fs::create_directories(out);
  std::ofstream(out / magfem::RunCheckpoint::file_name)
      << "{\"identity\":\"sweep --move other\"}\n{\"key\":\"0\",\"value\":{\"fz_N\":1}}\n";
  const auto r = finish(start_sweep("0:0.5:1", out, true), out);
  EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("--resume"), std::string::npos) << r.stderr_text;
  EXPECT_FALSE(fs::exists(out / "sweep.csv"));
}

namespace {

// results.csv without its seconds column (the time of each entry, which a rerun does not
// reproduce).
std::string results_without_seconds(const fs::path& csv) {
  return magfem::test::validation_csv_without_seconds(text_of(csv));
}

int run_validate(const fs::path& out, bool resume) {
  const std::string cmd =
      std::string(magfem::test::magfem_binary()) + " validate --source 002 --jobs 1 --out " +
      out.string() + (resume ? " --resume" : "") + " > /dev/null 2> " + out.string() + ".stderr";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

// validate keeps its finished entries too (issue 15): Ctrl-C once five entries of seed 002's
// (21 entries, ~7 s) are in the checkpoint, then --resume. Exit 130 and nothing but the
// checkpoint after the signal; the resumed run restores the entries it finds (says so per
// entry) and writes the results.csv of an uninterrupted run (but for the time column).
TEST(Interrupt, ResumedValidateWritesTheSameResultsAsAnUninterruptedRun) {
  const fs::path whole = test_dir("validate_whole"), cut = test_dir("validate_cut");
  fs::remove_all(whole);
  fs::remove_all(cut);
  ASSERT_EQ(run_validate(whole, false), 0) << text_of(whole.string() + ".stderr");

  const fs::path err = cut.string() + ".stderr";
  const pid_t pid =
      spawn_magfem({"validate", "--source", "002", "--jobs", "1", "--out", cut.string()}, cut);
  const fs::path checkpoint = cut / magfem::RunCheckpoint::file_name;
  auto lines = [&] {
    std::ifstream in(checkpoint);
    return std::count(std::istreambuf_iterator<char>(in), {}, '\n');
  };
  const auto t0 = std::chrono::steady_clock::now();
  while (lines() < 6 && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120))
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  kill(pid, SIGINT);
  const Outcome o = finish(pid, cut);
  ASSERT_EQ(o.exit_code, 130) << "the run ended before the signal: " << o.stderr_text;
  expect_nothing_written(cut);

  ASSERT_EQ(run_validate(cut, true), 0) << text_of(err);
  std::size_t resumed = 0;
  const std::string log = text_of(err);
  for (auto at = log.find(" resumed"); at != std::string::npos; at = log.find(" resumed", at + 1))
    ++resumed;
  EXPECT_GE(resumed, 5u) << log;
  EXPECT_LT(resumed, 21u) << log;
  EXPECT_EQ(results_without_seconds(cut / "results.csv"),
            results_without_seconds(whole / "results.csv"));
  EXPECT_FALSE(fs::exists(checkpoint)) << "the checkpoint outlived the committed outputs";
}

namespace {

// `magfem study` of the compensator prototype's torque against cylinder height: 11 designs of
// one analytic position each (the exterior-field interaction, 0.4-0.8 s a design on 2 cores).
pid_t start_study(const fs::path& out, bool resume, const std::string& objective = "torque_at:90") {
  std::vector<std::string> args = {
      "study",       magfem::test::example("3d/compensator_prototype_height_study.yaml"),
      "--param",     "height=5:2.5:30",
      "--objective", objective,
      "--rotate",    "outer",
      "--axis",      "y",
      "--jobs",      "1",
      "--out",       out.string()};
  if (resume)
    args.push_back("--resume");
  return spawn_magfem(args, out);
}

long lines_in(const fs::path& file) {
  std::ifstream in(file);
  return std::count(std::istreambuf_iterator<char>(in), {}, '\n');
}

} // namespace

// study keeps its finished designs like sweep and validate (issue 15): Ctrl-C once two designs
// are in the checkpoint (header + 2 lines; the signal follows within the 10 ms poll, while 9
// designs of 0.4-0.8 s each are left, so the run cannot finish first even on a machine ten
// times faster), then --resume. Exit 130 and nothing but the checkpoint; a checkpoint of other
// options is refused (exit 2); the resumed run restores the designs it finds (says how many)
// and writes the study.csv of an uninterrupted run byte for byte (the restored objectives are
// the computed doubles). Would fail if designs were not recorded as they finish, restored
// under the wrong parameters, re-rounded, or all evaluated again.
TEST(Interrupt, ResumedStudyWritesTheSameCsvAsAnUninterruptedRun) {
  const fs::path whole = test_dir("study_whole"), cut = test_dir("study_cut");
  fs::remove_all(whole);
  fs::remove_all(cut);
  const auto w = finish(start_study(whole, false), whole);
  ASSERT_EQ(w.exit_code, 0) << w.stderr_text;

  const pid_t pid = start_study(cut, false);
  const fs::path checkpoint = cut / magfem::RunCheckpoint::file_name;
  const auto t0 = std::chrono::steady_clock::now();
  while (lines_in(checkpoint) < 3 &&
         std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120))
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  kill(pid, SIGINT);
  const Outcome i = finish(pid, cut);
  ASSERT_EQ(i.exit_code, 130) << "the run ended before the signal: " << i.stderr_text;
  EXPECT_NE(i.stderr_text.find("interrupted by SIGINT"), std::string::npos) << i.stderr_text;
  expect_nothing_written(cut);
  ASSERT_TRUE(fs::exists(checkpoint));
  const long n_recorded = lines_in(checkpoint) - 1;
  EXPECT_GE(n_recorded, 2);
  EXPECT_LT(n_recorded, 11);

  const auto other = finish(start_study(cut, true, "torque_at:80"), cut);
  EXPECT_EQ(other.exit_code, 2) << other.stderr_text;
  EXPECT_NE(other.stderr_text.find("--resume"), std::string::npos) << other.stderr_text;
  EXPECT_EQ(lines_in(checkpoint) - 1, n_recorded) << "a refused resume leaves the checkpoint be";

  const auto r = finish(start_study(cut, true), cut);
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      r.stderr_text, m, std::regex("--resume: ([0-9]+) finished designs from the checkpoint")))
      << r.stderr_text;
  EXPECT_EQ(std::stol(m[1]), n_recorded);
  EXPECT_EQ(text_of(cut / "study.csv"), text_of(whole / "study.csv"));
  EXPECT_FALSE(fs::exists(checkpoint)) << "the checkpoint outlived the committed outputs";
}
