// `mpirun -n 2 magfem solve` against the serial run of the same small linear 3D case
// (examples/3d/magnet_and_ball_small.yaml): both succeed, summary.json says 1 and 2 ranks, the
// energy and every probe value agree to the solver tolerance, and the distributed run wrote
// one set of outputs and printed one report. Cases the distributed mode refuses end quickly
// with exit 2 on every process instead of hanging; a Krylov failure with exit 3.
//
// `mpirun -n 2|3 magfem sweep` (positions dealt to the processes, rank 0 writing): the serial
// run's sweep.csv (and plot) byte for byte and its summary.json but for the times; --resume
// under mpirun takes a serial run's checkpoint and solves only the positions it lacks; a bad
// option or group ends every process with exit 2 and no outputs, never a hang.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "tests/case_helpers.hpp"
#include "tests/cli/mpi_helpers.hpp"
#include "tests/run_cli.hpp"

namespace fs = std::filesystem;
using magfem::test::CliOutcome;
using magfem::test::fresh_dir;
using magfem::test::mpirun_path;
using magfem::test::probe_difference;
using magfem::test::read_json;
using magfem::test::run_mpi;
using magfem::test::text_of;

namespace {

// Both runs stop CG at |b - A x| <= 1e-12 |b| (the case's linear_tolerance), so the two
// solutions differ by e with |A e| <= 2e-12 |b|, i.e. |e| / |x| <= 2e-12 cond(A). For this P1
// mesh with its mu_r 100 ball and open-boundary shell cond(A) is below ~1e5, so the fields
// (and the energy, a smooth function of them) agree to ~2e-7 in the worst case; 1e-6 leaves
// room for the probe files' printed digits. An assembly or gather error (a rank's elements
// twice or missing, a solution block misplaced) changes them by percents.
constexpr double agreement_tol = 1e-6;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

class Mpi : public ::testing::Test {
protected:
  void SetUp() override {
    if (mpirun_path().empty())
      GTEST_SKIP() << "mpirun not found (Debian: mpi-default-bin, scripts/install_deps.sh)";
  }
};

TEST_F(Mpi, TwoRanksGiveTheSerialFieldWithOneSetOfOutputs) {
  const std::string example = magfem::test::example("3d/magnet_and_ball_small.yaml");
  const fs::path serial_dir = fresh_dir("serial"), mpi_dir = fresh_dir("two_ranks");
  const CliOutcome serial =
      magfem::test::run_cli("solve " + example + " --out " + serial_dir.string());
  ASSERT_EQ(serial.status, 0) << serial.out;
  const CliOutcome mpi = run_mpi(2, "solve " + example + " --out " + mpi_dir.string());
  ASSERT_EQ(mpi.status, 0) << mpi.out;

  const auto s = read_json(serial_dir / "summary.json");
  const auto m = read_json(mpi_dir / "summary.json");
  EXPECT_EQ(s["ranks"], 1);
  EXPECT_EQ(m["ranks"], 2);
  EXPECT_EQ(m["unknowns"], s["unknowns"]);
  EXPECT_EQ(m["linear_solver"], "cg");
  EXPECT_EQ(m["preconditioner"], "boomeramg");
  const double e_serial = s["energy_J"], e_mpi = m["energy_J"];
  const double energy_rel = std::abs(e_mpi - e_serial) / std::abs(e_serial);
  EXPECT_LE(energy_rel, agreement_tol) << e_serial << " J serially, " << e_mpi << " J on 2 ranks";
  std::printf("energy: serial %.15g J, 2 ranks %.15g J, relative difference %.2e (tolerance "
              "%.0e)\n",
              e_serial, e_mpi, energy_rel, agreement_tol);

  ASSERT_FALSE(m["probes"].empty());
  for (const auto& name : m["probes"]) {
    const std::string file = name;
    const double d = probe_difference(magfem::read_probe_csv((serial_dir / file).string()),
                                      magfem::read_probe_csv((mpi_dir / file).string()));
    EXPECT_LE(d, agreement_tol) << file;
    std::printf("%s: largest B difference %.2e of the largest |B|\n", file.c_str(), d);
  }

  // One set of outputs: exactly the serial run's files, no staging folder or stray copy left
  // by a second writer; one report on the console.
  std::set<std::string> serial_files, mpi_files;
  for (const auto& e : fs::directory_iterator(serial_dir))
    serial_files.insert(e.path().filename().string());
  for (const auto& e : fs::directory_iterator(mpi_dir))
    mpi_files.insert(e.path().filename().string());
  EXPECT_EQ(mpi_files, serial_files);
  EXPECT_EQ(count(mpi.out, "wrote    "), 1u) << mpi.out;
  EXPECT_EQ(count(mpi.out, "energy   "), 1u) << mpi.out;
  fs::remove_all(serial_dir.parent_path());
}

// Rank 0 post-processes alone once the solve is done; the other processes on its machine lend
// it their cores (lend_node_cores_to_root), so its loops are not confined to the one core
// mpirun bound it to. Bound one core each, rank 0 reports both cores in summary.json.
// Planted: the lending skipped (no sched_setaffinity) -> 1 core -> fails.
TEST_F(Mpi, RankZeroPostProcessesOnTheCoresTheOtherProcessLendsIt) {
  if (sysconf(_SC_NPROCESSORS_ONLN) < 2)
    GTEST_SKIP() << "one core: nothing to lend";
  const std::string example = magfem::test::example("3d/magnet_and_ball_small.yaml");
  const fs::path dir = fresh_dir("lent_cores");
  const CliOutcome mpi =
      run_mpi(2, "solve " + example + " --quiet --out " + dir.string(), 400, "--bind-to core");
  ASSERT_EQ(mpi.status, 0) << mpi.out;
  EXPECT_EQ(read_json(dir / "summary.json")["post_processing_cores"], 2) << mpi.out;
  fs::remove_all(dir.parent_path());
}

// Refusals come before any meshing, on every process alike, with exit 2: never a hang.
// (Coils and nonlinear iron are distributed: test_mpi_solve.cpp.)
TEST_F(Mpi, RefusedCasesEndWithExitTwo) {
  const fs::path out = fresh_dir("refused");
  const CliOutcome planar =
      run_mpi(2, "solve " + magfem::test::example("2d/c_core.yaml") + " --out " + out.string());
  EXPECT_EQ(planar.status, 2) << planar.out;
  EXPECT_NE(planar.out.find("without mpirun"), std::string::npos) << planar.out;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  fs::remove_all(out.parent_path());
}

// A CG that stops on its iteration limit is a solver failure on every process alike: exit 3,
// no outputs, no process left waiting.
TEST_F(Mpi, KrylovFailureIsExitThreeWithoutOutputs) {
  std::ifstream in(magfem::test::example("3d/magnet_and_ball_small.yaml"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string tol = "  linear_tolerance: 1e-12";
  ASSERT_NE(text.find(tol), std::string::npos);
  text.replace(text.find(tol), tol.size(), "  linear_max_iterations: 3\n" + tol);
  const fs::path dir = fresh_dir("krylov_failure");
  fs::create_directories(dir);
  const fs::path case_file = dir / "three_iterations.yaml";
  std::ofstream(case_file) << text;
  const CliOutcome o =
      run_mpi(2, "solve " + case_file.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(o.status, 3) << o.out;
  EXPECT_NE(o.out.find("did not converge"), std::string::npos) << o.out;
  EXPECT_FALSE(fs::exists(dir / "out" / "summary.json"));
  fs::remove_all(dir.parent_path());
}

// The voice coil's coil moved through 6 positions, coarse (0.1-0.3 s a position): a sweep
// whose every row goes through the dealer and the row codec. Serially with --jobs 1 it is the
// reference the processes must reproduce.
const std::string voice_coil_sweep = " --move coil --axis z --positions 0:1:5 --mesh-scale 3";

// summary.json without what a rerun does not reproduce: each position's wall-clock `seconds`
// and the process's peak memory (rank 0's, which also solved some positions).
nlohmann::json without_times(const fs::path& summary) {
  auto j = read_json(summary);
  j.erase("peak_memory_MB");
  for (auto& p : j["positions"])
    p.erase("seconds");
  return j;
}

CliOutcome serial_sweep(const std::string& case_and_motion, const fs::path& out) {
  return magfem::test::run_cli("sweep " + case_and_motion + " --jobs 1 --quiet --out " +
                               out.string());
}

// Byte-identical outputs need every row at its position's place whatever process solved it,
// every double exact through the row codec, no position lost or solved twice. Would fail on:
// rows written in arrival order, a position skipped by a process, a row's force re-rounded,
// a row solved on two processes (a duplicated CSV line).
TEST_F(Mpi, SweepDealtToTwoAndThreeProcessesWritesTheSerialOutputs) {
  const std::string sweep =
      "sweep " + magfem::test::example("axi/voice_coil_magnet.yaml") + voice_coil_sweep;
  const fs::path serial = fresh_dir("sweep_serial");
  const CliOutcome s =
      serial_sweep(magfem::test::example("axi/voice_coil_magnet.yaml") + voice_coil_sweep, serial);
  ASSERT_EQ(s.status, 0) << s.out;
  for (const int n : {2, 3}) {
    const fs::path dir = fresh_dir("sweep_" + std::to_string(n) + "_ranks");
    const CliOutcome m = run_mpi(n, sweep + " --out " + dir.string());
    ASSERT_EQ(m.status, 0) << m.out;
    EXPECT_EQ(text_of(dir / "sweep.csv"), text_of(serial / "sweep.csv")) << n << " processes";
    EXPECT_EQ(without_times(dir / "summary.json"), without_times(serial / "summary.json"));
    EXPECT_EQ(count(m.out, "wrote    "), 1u) << m.out;
    EXPECT_EQ(count(m.out, "sweep on " + std::to_string(n) + " processes"), 1u) << m.out;
    EXPECT_FALSE(fs::exists(dir / ".magfem-checkpoint.jsonl"));
  }
  fs::remove_all(serial.parent_path());
}

// The planar sweep (the 3D sweep's row type and codec) with its plot: sweep.png too is the
// serial run's, byte for byte (drawn from the same rows).
TEST_F(Mpi, PlanarSweepOnTwoProcessesWritesTheSerialCsvAndPlot) {
  const std::string motion = magfem::test::example("2d/re25_motor_torque.yaml") +
                             " --rotate rotor --axis z --angles 0,120";
  const fs::path serial = fresh_dir("planar_serial"), dir = fresh_dir("planar_2_ranks");
  const CliOutcome s = serial_sweep(motion, serial);
  ASSERT_EQ(s.status, 0) << s.out;
  const CliOutcome m = run_mpi(2, "sweep " + motion + " --quiet --out " + dir.string());
  ASSERT_EQ(m.status, 0) << m.out;
  EXPECT_EQ(text_of(dir / "sweep.csv"), text_of(serial / "sweep.csv"));
  EXPECT_EQ(without_times(dir / "summary.json"), without_times(serial / "summary.json"));
  if (fs::exists(serial / "sweep.png")) { // gnuplot installed
    EXPECT_EQ(text_of(dir / "sweep.png"), text_of(serial / "sweep.png"));
  }
  fs::remove_all(serial.parent_path());
}

// A checkpoint of positions 0, 2 and 4 mm (left by a serial run whose outputs could not be
// committed: a directory stands where sweep.csv goes), then --resume under mpirun: the
// serial sweep.csv of all six, and the three restored rows keep the checkpoint's times
// (solved again, they would have new ones). Would fail if the processes ignored the
// checkpoint, if a restored position were dealt again, or if the rows were placed by arrival.
TEST_F(Mpi, ResumedSweepUnderMpirunSolvesOnlyTheMissingPositions) {
  const std::string case_file = magfem::test::example("axi/voice_coil_magnet.yaml");
  const fs::path serial = fresh_dir("resume_serial"), dir = fresh_dir("resume_2_ranks");
  ASSERT_EQ(serial_sweep(case_file + voice_coil_sweep, serial).status, 0);
  fs::create_directories(dir / "sweep.csv" / "blocker");
  const CliOutcome cut =
      magfem::test::run_cli("sweep " + case_file +
                            " --move coil --axis z --positions 0,2,4 --mesh-scale 3 --jobs 1 "
                            "--quiet --out " +
                            dir.string());
  ASSERT_EQ(cut.status, 1) << cut.out;
  const fs::path checkpoint = dir / ".magfem-checkpoint.jsonl";
  ASSERT_TRUE(fs::exists(checkpoint));
  std::map<double, double> seconds_of; // position (mm) -> its time in the checkpoint
  std::stringstream lines(text_of(checkpoint));
  std::string line;
  std::getline(lines, line); // the identity
  while (std::getline(lines, line)) {
    const auto entry = nlohmann::json::parse(line);
    seconds_of[std::round(1e3 * std::stod(entry["key"].get<std::string>()))] =
        entry["value"]["seconds"];
  }
  ASSERT_EQ(seconds_of.size(), 3u);
  fs::remove_all(dir / "sweep.csv");

  const CliOutcome m =
      run_mpi(2, "sweep " + case_file + voice_coil_sweep + " --resume --out " + dir.string());
  ASSERT_EQ(m.status, 0) << m.out;
  EXPECT_NE(m.out.find("--resume: 3 finished positions"), std::string::npos) << m.out;
  EXPECT_EQ(text_of(dir / "sweep.csv"), text_of(serial / "sweep.csv"));
  int restored = 0;
  const auto summary = read_json(dir / "summary.json");
  for (const auto& p : summary["positions"]) {
    const double mm = std::round(p["position_mm"].get<double>());
    if (seconds_of.count(mm)) {
      EXPECT_EQ(p["seconds"].get<double>(), seconds_of[mm]) << mm << " mm solved again";
      ++restored;
    }
  }
  EXPECT_EQ(restored, 3);
  EXPECT_FALSE(fs::exists(checkpoint));
  fs::remove_all(serial.parent_path());
}

// Every process reads the same options and case, so each fails alike before the positions
// are dealt: exit 2 from all, through MPI_Abort, within the timeout, nothing written.
TEST_F(Mpi, BadSweepInputEndsEveryProcessWithExitTwo) {
  const std::string case_file = magfem::test::example("axi/voice_coil_magnet.yaml");
  const fs::path dir = fresh_dir("sweep_bad");
  const CliOutcome option =
      run_mpi(2, "sweep " + case_file + voice_coil_sweep + " --bogus --out " + dir.string());
  EXPECT_EQ(option.status, 2) << option.out;
  EXPECT_NE(option.out.find("--bogus"), std::string::npos) << option.out;
  const CliOutcome group = run_mpi(
      3, "sweep " + case_file + " --move nosuch --axis z --positions 0:1:5 --out " + dir.string());
  EXPECT_EQ(group.status, 2) << group.out;
  EXPECT_NE(group.out.find("nosuch"), std::string::npos) << group.out;
  EXPECT_FALSE(fs::exists(dir / "sweep.csv"));
  EXPECT_FALSE(fs::exists(dir / "summary.json"));
  fs::remove_all(dir.parent_path());
}

} // namespace
