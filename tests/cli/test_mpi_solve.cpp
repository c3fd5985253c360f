// The distributed 3D solve with coils, nonlinear iron and p-multigrid (issue 33 item 2):
// `mpirun -n N magfem solve` against the serial run of the same case, for a coil over a
// permeable plate (the coil source field evaluated per process, the inductance's sensitivity
// solve distributed), a magnet over a saturable steel plate (Newton with distributed residuals
// and tangents) and a P2 magnetized sphere with CG + pmg (the CG iteration count within 1.2x
// of the serial one on 2 processes, 1.5x on 3); P2 (coils too) by own-row assembly (each
// process the tetrahedra of its own rows, solver/distributed_rows.hpp), which the note says. The
// energy and the coil's flux linkage agree to 1e-8, the inductance to 1e-6 (both runs' sensitivity
// solves are loose and corrected), and every probe value to 1e-6 of the largest |B|; a Newton that
// does not converge ends every process with exit 3 and writes nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/case_helpers.hpp"
#include "tests/cli/mpi_helpers.hpp"

namespace fs = std::filesystem;
using magfem::test::CliOutcome;

namespace {

// Serial runs factorize (CHOLMOD) or solve by CG with p-multigrid, distributed ones by CG with
// BoomerAMG; the cases ask both to stop CG at 1e-12 (and Newton at its 1e-9 residual and
// update). The energy is stationary at the discrete solution, so it moves with the square of
// the solution difference: measured 1e-16 to 1e-12 relative (coil, magnet over steel), so 1e-8
// (the target) has room for other machines' rounding. Fields are linear in the
// solution: probes to 1e-6 of the largest |B| (the target; measured ~1e-10). A rank's
// share of the source load or of the matrix lost changes these by percents.
constexpr double energy_tol = 1e-8;
constexpr double probe_tol = 1e-6;
// The inductance's sensitivity solves stop at 1e-5 in both runs (pmg serially, BoomerAMG
// distributed) and the matrix takes the variational correction (current_sensitivity3d.hpp),
// which leaves the product of two solve errors: 3.4e-7 of the largest entry serially against
// solves to 1e-12 (test_inductance3d), 4.0e-7 between the two runs here. Without the
// correction the distributed matrix is off by CG's own 1e-5.
constexpr double inductance_tol = 1e-6;

// `example` with `solver:` replaced (tolerances tight enough to compare runs), written to
// `dir`.
fs::path write_case(const fs::path& dir, const std::string& example, const std::string& solver) {
  std::ifstream in(magfem::test::example(example));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string old = "solver: {order: 2}";
  const auto at = text.find(old);
  EXPECT_NE(at, std::string::npos) << example;
  if (at != std::string::npos)
    text.replace(at, old.size(), solver);
  fs::create_directories(dir);
  const fs::path file = dir / fs::path(example).filename();
  std::ofstream(file) << text;
  return file;
}

double relative(double a, double b) {
  return std::abs(a - b) / std::max(std::abs(a), 1e-300);
}

// The serial run of `args` (its outputs in dir/serial), then `mpirun -n <n>` of it (dir/ranks_n),
// and every comparison: ranks, energy, each region's energy, coils' linkage and inductance,
// probes.
void expect_serial_field(const fs::path& dir, const std::string& args, int n, int timeout_s = 400) {
  const fs::path serial_dir = dir / "serial", mpi_dir = dir / ("ranks_" + std::to_string(n));
  if (!fs::exists(serial_dir / "summary.json")) {
    const CliOutcome serial =
        magfem::test::run_cli("solve " + args + " --out " + serial_dir.string());
    ASSERT_EQ(serial.status, 0) << serial.out;
  }
  const CliOutcome mpi =
      magfem::test::run_mpi(n, "solve " + args + " --out " + mpi_dir.string(), timeout_s);
  ASSERT_EQ(mpi.status, 0) << mpi.out;
  const auto s = magfem::test::read_json(serial_dir / "summary.json");
  const auto m = magfem::test::read_json(mpi_dir / "summary.json");
  EXPECT_EQ(m["ranks"], n);
  const double e = relative(s["energy_J"], m["energy_J"]);
  EXPECT_LE(e, energy_tol) << s["energy_J"] << " J serially, " << m["energy_J"] << " J on " << n;
  std::printf("%d ranks: energy %.17g J against %.17g J, relative difference %.2e\n", n,
              double(m["energy_J"]), double(s["energy_J"]), e);
  ASSERT_EQ(m["regions"].size(), s["regions"].size());
  for (std::size_t i = 0; i < s["regions"].size(); ++i)
    if (s["regions"][i].is_object()) {
      EXPECT_LE(relative(s["regions"][i]["energy_J"], m["regions"][i]["energy_J"]), energy_tol)
          << s["regions"][i]["name"];
    }
  if (s.contains("coils")) {
    ASSERT_EQ(m["coils"].size(), s["coils"].size());
    for (std::size_t k = 0; k < s["coils"].size(); ++k) {
      const double l = relative(s["coils"][k]["flux_linkage_Wb"], m["coils"][k]["flux_linkage_Wb"]);
      const double ind = relative(s["coils"][k]["inductance_H"], m["coils"][k]["inductance_H"]);
      EXPECT_LE(l, energy_tol) << "linkage of coil " << k;
      EXPECT_LE(ind, inductance_tol) << "inductance of coil " << k;
      std::printf("coil %zu: linkage differs by %.2e, inductance by %.2e\n", k, l, ind);
    }
  }
  for (const auto& name : s.value("probes", nlohmann::json::array())) {
    const std::string file = name;
    const double d =
        magfem::test::probe_difference(magfem::read_probe_csv((serial_dir / file).string()),
                                       magfem::read_probe_csv((mpi_dir / file).string()));
    EXPECT_LE(d, probe_tol) << file;
    std::printf("%s: largest B difference %.2e of the largest |B|\n", file.c_str(), d);
  }
}

class MpiSolve : public ::testing::Test {
protected:
  void SetUp() override {
    if (magfem::test::mpirun_path().empty())
      GTEST_SKIP() << "mpirun not found (Debian: mpi-default-bin, scripts/install_deps.sh)";
  }
};

// Coarse P1 variants (seconds a run): the distributed code paths are those of P2.
std::string coil_case(const fs::path& dir) {
  return write_case(dir, "3d/coil_over_plate.yaml", "solver: {order: 1, linear_tolerance: 1e-12}")
             .string() +
         " --mesh-scale 4";
}

std::string steel_case(const fs::path& dir) {
  return write_case(dir, "3d/magnet_over_steel_plate.yaml",
                    "solver: {order: 1, linear_tolerance: 1e-12}")
             .string() +
         " --mesh-scale 4";
}

// P2 with p-multigrid (issue 33 step 1): serially CG + pmg, distributed the same two levels on
// a partition of the mesh with the open-boundary shell whole on process 0, and the serial
// smoother's Gauss-Seidel sweeps over all processes' rows, the rows that read other processes'
// unknowns last and process after process (solver/smoother_sweeps.hpp). The count then stays
// the serial one: measured 22 / 22 / 22 CG iterations on 1 / 2 / 3 processes here, and 14 / 14
// without a shell (symmetric Gauss-Seidel, as the serial SSOR), so the distributed count may
// exceed it by one iteration at most (1.05x). Block Jacobi across the processes (each from
// the others' old values) took 23-24 / 24-27 with the shell, which it catches on 3 processes,
// and 15-17 without; a coarse operator off by a factor 2 (not P^T A P) took 30 and 20. The
// coil and iron cases (Newton's steps add their counts) measured 23 / 23 and 32 / 30 at
// --mesh-scale 6 on 2 processes, and 22 / 22-23 and 27 / 28 at 4 on 2 and 3: within 1.07x,
// so 1.1x (the bound was 1.5x).
constexpr double pmg_iteration_ratio = 1.1;
constexpr double pmg_iteration_ratio_linear = 1.05;

// The magnetized sphere, P2, CG + pmg to 1e-12 serially and distributed, coarse (35k
// unknowns: seconds a run); `open` = false: a Dirichlet sphere, no shell (the smoother is
// symmetric Gauss-Seidel then).
std::string sphere_pmg_case(const fs::path& dir, bool open) {
  const fs::path file =
      write_case(dir, "3d/magnetized_sphere.yaml",
                 "solver: {order: 2, preconditioner: pmg, linear_tolerance: 1e-12}");
  if (!open) {
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string shell = "boundary: {type: open, radius: 25, shell_ratio: 1.5}";
    const auto at = text.find(shell);
    EXPECT_NE(at, std::string::npos);
    if (at != std::string::npos)
      text.replace(at, shell.size(), "boundary: {type: dirichlet, radius: 25}");
    in.close();
    std::ofstream(file) << text;
  }
  return file.string() + " --mesh-scale 5";
}

// `example` as P2 with CG + pmg to 1e-12 (serially and distributed), at `mesh_scale`.
std::string p2_pmg_case(const fs::path& dir, const std::string& example,
                        const std::string& mesh_scale) {
  return write_case(dir, example,
                    "solver: {order: 2, preconditioner: pmg, linear_tolerance: 1e-12}")
             .string() +
         " --mesh-scale " + mesh_scale;
}

// expect_serial_field, and both runs used pmg with the distributed one's CG iterations within
// `ratio` of the serial one's; `own_rows`: each process assembled the tetrahedra of its own
// rows (solver/distributed_rows.hpp; P2 with pmg), which the note says.
void expect_serial_pmg(const fs::path& dir, const std::string& args, int n, double ratio,
                       bool own_rows = true) {
  expect_serial_field(dir, args, n);
  const auto s = magfem::test::read_json(dir / "serial" / "summary.json");
  const auto m = magfem::test::read_json(dir / ("ranks_" + std::to_string(n)) / "summary.json");
  EXPECT_EQ(s["preconditioner"], "pmg");
  EXPECT_EQ(m["preconditioner"], "pmg");
  const int serial = s["linear_iterations"], distributed = m["linear_iterations"];
  EXPECT_LE(distributed, ratio * serial) << serial << " serially";
  std::printf("%d ranks: %d CG + pmg iterations against %d serially\n", n, distributed, serial);
  ASSERT_EQ(m["solver_notes"].size(), 1u);
  const std::string note = m["solver_notes"][0];
  EXPECT_NE(note.find("p-multigrid"), std::string::npos);
  EXPECT_EQ(note.find("tetrahedra of its own rows") != std::string::npos, own_rows) << note;
}

// Every line is one of the report's ("mesh     26729 tetrahedra, ...").
bool only_report_lines(const std::string& text) {
  static const std::regex report_line("[a-z][a-z ]{7} [^ ].*");
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (!std::regex_match(line, report_line))
      return false;
  return true;
}

} // namespace

// The open-boundary shell: its block on process 0, by Cholesky.
TEST_F(MpiSolve, PmgOnTwoAndThreeProcessesKeepsTheSerialField) {
  const fs::path dir = magfem::test::fresh_dir("sphere_pmg");
  const std::string args = sphere_pmg_case(dir, true);
  for (int n : {2, 3})
    expect_serial_pmg(dir, args, n, pmg_iteration_ratio_linear);
  fs::remove_all(dir);
}

// The same case on the same processes twice gives the same bytes: the mesh's partition is
// the same in every run (solver/pmg_partition.hpp). With PT-Scotch over the processes, or
// Scotch seeded from the clock or on several threads, the parts (and so the smoother, the
// CG iterates and the last digits of every output) changed from run to run.
TEST_F(MpiSolve, TwoRunsOnTwoProcessesWriteTheSameBytes) {
  const fs::path dir = magfem::test::fresh_dir("sphere_pmg_twice");
  const std::string args = sphere_pmg_case(dir, true);
  const auto slurp = [](const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  for (const char* run : {"first", "second"}) {
    const CliOutcome mpi =
        magfem::test::run_mpi(2, "solve " + args + " --quiet --out " + (dir / run).string());
    ASSERT_EQ(mpi.status, 0) << mpi.out;
    // Nothing on the console but rank 0's report ("energy   0.55 J": a key of lower-case
    // letters padded to 9 columns): a debug line of the partition ("PARTHASH 0 ...") went to
    // stderr from every process of every distributed pmg solve from cfba218 until this check.
    EXPECT_TRUE(only_report_lines(mpi.out)) << mpi.out;
  }
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(dir / "first"))
    if (entry.path().extension() == ".csv") {
      ++compared;
      EXPECT_EQ(slurp(entry.path()), slurp(dir / "second" / entry.path().filename()))
          << entry.path().filename();
    }
  EXPECT_GE(compared, 2); // the case's probe tables
  const auto a = magfem::test::read_json(dir / "first" / "summary.json");
  const auto b = magfem::test::read_json(dir / "second" / "summary.json");
  EXPECT_EQ(a["energy_J"], b["energy_J"]);
  EXPECT_EQ(a["linear_iterations"], b["linear_iterations"]);
  fs::remove_all(dir);
}

// No shell: symmetric Gauss-Seidel over all processes' rows, as the serial SSOR.
TEST_F(MpiSolve, PmgWithoutShellOnTwoProcessesKeepsTheSerialField) {
  const fs::path dir = magfem::test::fresh_dir("sphere_pmg_dirichlet");
  expect_serial_pmg(dir, sphere_pmg_case(dir, false), 2, pmg_iteration_ratio_linear);
  fs::remove_all(dir);
}

// P2 with pmg for a coil (the inductance's sensitivity solves on the distributed pmg too) and
// for Newton on saturable steel (the partition and each process's shell factor kept across
// the steps), both by own-row assembly, on 2 and 3 processes: 10-20 s a run, label long.
TEST_F(MpiSolve, LongP2CoilAndNonlinearCasesWithPmgOnTwoAndThreeProcesses) {
  for (const std::string example : {"3d/coil_over_plate.yaml", "3d/magnet_over_steel_plate.yaml"}) {
    const fs::path dir = magfem::test::fresh_dir("p2_" + fs::path(example).stem().string());
    const std::string args = p2_pmg_case(dir, example, "4");
    for (int n : {2, 3})
      expect_serial_pmg(dir, args, n, pmg_iteration_ratio);
    fs::remove_all(dir);
  }
}

// Own-row assembly with a coil: each process evaluates the coil's source field at the
// tetrahedra of its rows, ghost ones included (which a neighbour evaluates too), and rank 0
// gets the whole table for the post-processing (solver/source_field_table3d.hpp); the
// inductance's sensitivity solves over the same rows. P2 coil over a permeable plate, coarse
// (99k unknowns, 5-10 s a run; 3 processes in the long test above). A ghost tetrahedron's
// source field missing or counted twice in the gathered table moves the energy and the
// linkage by far more than 1e-8.
TEST_F(MpiSolve, OwnRowAssemblyOfACoilCaseOnTwoProcessesKeepsTheSerialField) {
  const fs::path dir = magfem::test::fresh_dir("coil_own_rows");
  const std::string args = p2_pmg_case(dir, "3d/coil_over_plate.yaml", "6");
  expect_serial_pmg(dir, args, 2, pmg_iteration_ratio);
  fs::remove_all(dir);
}

// Own-row assembly with Newton: every residual, the line search's too, from the rows each
// process owns (the tetrahedra of its rows assembled, ghost ones included), P2 magnet over
// saturable steel, coarse (107k unknowns, ~6 s a run).
TEST_F(MpiSolve, OwnRowAssemblyOfNonlinearIronOnTwoProcessesGivesTheSerialField) {
  const fs::path dir = magfem::test::fresh_dir("steel_own_rows");
  const std::string args = p2_pmg_case(dir, "3d/magnet_over_steel_plate.yaml", "6");
  expect_serial_pmg(dir, args, 2, pmg_iteration_ratio);
  fs::remove_all(dir);
}

// The coil's source field on each process's own tetrahedra, the distributed inductance solve.
TEST_F(MpiSolve, CoilCaseOnTwoProcessesGivesTheSerialField) {
  const fs::path dir = magfem::test::fresh_dir("coil");
  expect_serial_field(dir, coil_case(dir), 2);
  fs::remove_all(dir);
}

// A mesh large enough for TetGen's two pieces (benchmark32, P1, 0.5 M tetrahedra, cut at the
// magnets' outer sphere, 55 mm): under mpirun process 0 meshes the inner piece and process 1
// the outer one, and each stitches both (pipeline/mesh_pieces_on_processes.hpp). The same mesh
// as the serial run's two threads, so the field to the solver tolerance, on 2 and 3 processes;
// a piece meshed with another random sequence or stitched with its points misnumbered moves the
// energy by far more than 1e-8 (or fails the processes' fingerprint check).
TEST_F(MpiSolve, SplitMeshMeshedOnePiecePerProcessKeepsTheSerialField) {
  const fs::path dir = magfem::test::fresh_dir("split_mesh");
  const std::string args =
      write_case(dir, "3d/benchmark32_parallel.yaml", "solver: {order: 1, linear_tolerance: 1e-12}")
          .string() +
      " --mesh-scale 4";
  for (int n : {2, 3}) {
    expect_serial_field(dir, args, n);
    const auto s = magfem::test::read_json(dir / "serial" / "summary.json");
    const auto m = magfem::test::read_json(dir / ("ranks_" + std::to_string(n)) / "summary.json");
    EXPECT_EQ(s["mesh_split_radius_mm"], 55.0);
    EXPECT_EQ(m["mesh_split_radius_mm"], 55.0);
    EXPECT_EQ(m["elements"], s["elements"]);
    EXPECT_EQ(m["nodes"], s["nodes"]);
  }
  fs::remove_all(dir);
}

// Newton with every residual (the line search's too) summed over the processes.
TEST_F(MpiSolve, NonlinearCaseOnTwoProcessesGivesTheSerialField) {
  const fs::path dir = magfem::test::fresh_dir("steel");
  expect_serial_field(dir, steel_case(dir), 2);
  fs::remove_all(dir);
}

// Newton stopped after two iterations: every process sees the same residuals and gives up
// together, exit 3 on all, nothing written, no process left waiting (the timeout's 124).
TEST_F(MpiSolve, NewtonThatDoesNotConvergeEndsEveryProcessWithoutOutputs) {
  const fs::path dir = magfem::test::fresh_dir("newton_failure");
  const fs::path file =
      write_case(dir, "3d/magnet_over_steel_plate.yaml", "solver: {order: 1, max_iterations: 2}");
  const CliOutcome o = magfem::test::run_mpi(
      2, "solve " + file.string() + " --mesh-scale 4 --out " + (dir / "out").string());
  EXPECT_EQ(o.status, 3) << o.out;
  EXPECT_NE(o.out.find("did not converge"), std::string::npos) << o.out;
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

// One process under mpirun (the serial path) and three (an uneven split of the elements and
// rows): label long.
TEST_F(MpiSolve, LongCoilAndNonlinearCasesOnOneAndThreeProcesses) {
  const fs::path coil = magfem::test::fresh_dir("coil_1_3");
  for (int n : {1, 3})
    expect_serial_field(coil, coil_case(coil), n);
  fs::remove_all(coil);
  const fs::path steel = magfem::test::fresh_dir("steel_1_3");
  for (int n : {1, 3})
    expect_serial_field(steel, steel_case(steel), n);
  fs::remove_all(steel);
}

// TEAM 20 (nonlinear steel driven by a coil; the third case), coarse P1 (44k
// tetrahedra: half a minute a run, most of it the coil's source field): the pole force too.
TEST_F(MpiSolve, LongTeam20OnTwoAndThreeProcesses) {
  const fs::path dir = magfem::test::fresh_dir("team20");
  const std::string args =
      write_case(dir, "3d/team20.yaml", "solver: {order: 1, linear_tolerance: 1e-12}").string() +
      " --mesh-scale 6";
  for (int n : {2, 3}) {
    expect_serial_field(dir, args, n, 600);
    const auto s = magfem::test::read_json(dir / "serial" / "summary.json");
    const auto m = magfem::test::read_json(dir / ("ranks_" + std::to_string(n)) / "summary.json");
    ASSERT_FALSE(s["forces"].empty());
    const double fz = s["forces"][0]["force_N"][2], fz_mpi = m["forces"][0]["force_N"][2];
    EXPECT_LE(relative(fz, fz_mpi), probe_tol) << fz << " N against " << fz_mpi << " N";
  }
  fs::remove_all(dir);
}
