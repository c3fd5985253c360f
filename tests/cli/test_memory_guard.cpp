// The memory guard (pipeline/memory_guard.hpp) through the binary: a 3D case whose estimated peak
// memory exceeds --max-memory stops with exit 2 before meshing, writes nothing, and names a
// --mesh-scale; that scale does fit: the run it proposes passes the guard and its measured
// peak memory stays under the limit (the estimate's calibration, docs/performance.md "Memory guard
// calibration"). The case is a box magnet: flat faces, so no chord limit stops the mesh from
// coarsening. A parallel sweep shares the limit among the positions that run at once.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include "tests/case_helpers.hpp"
#include "tests/run_cli.hpp"

namespace fs = std::filesystem;

namespace {

using magfem::test::run_cli;

// Under AddressSanitizer (scripts/sanitize.sh) a run's resident memory includes the shadow
// memory and the quarantine of freed blocks, several times the model's figures: the limits
// on the measured peak are checked in normal builds only; everything else is checked in both.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool peak_memory_is_the_runs_own = false;
#else
constexpr bool peak_memory_is_the_runs_own = true;
#endif
} // namespace

TEST(MemoryGuard, ATinyLimitStopsBeforeMeshingAndTheProposedMeshScaleFits) {
  const fs::path out = fs::temp_directory_path() / "magfem_tests" / "memory_guard";
  fs::remove_all(out);
  const std::string case_file = magfem::test::write_temp_case("guard_box.yaml", R"(title: box magnet
dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.05}
regions:
  - {name: block, shape: box, size: [20, 20, 10], material: pm,
     magnetization: {type: parallel, direction: [0, 0, 1]}, mesh_size: 1.5}
boundary: {type: open, radius: 40, shell_ratio: 1.5}
mesh: {size: 5}
solver: {order: 1}
)");
  const std::string base = "solve " + case_file +
                           " --quiet --max-memory " MEMORY_GUARD_LIMIT_GB " --out " + out.string();
  const auto refused = run_cli(base);
  ASSERT_EQ(refused.status, 2) << refused.out;
  EXPECT_NE(refused.out.find("--max-memory"), std::string::npos) << refused.out;
  EXPECT_FALSE(fs::exists(out)) << "nothing is written";
  std::smatch m;
  ASSERT_TRUE(std::regex_search(refused.out, m, std::regex("--mesh-scale ([0-9.]+) would fit")))
      << refused.out;
  const std::string scale = m[1];

  const auto fits = run_cli(base + " --mesh-scale " + scale);
  ASSERT_EQ(fits.status, 0) << fits.out;
  std::stringstream text;
  text << std::ifstream(out / "summary.json").rdbuf();
  const auto summary = nlohmann::json::parse(text.str());
  const double limit_mb = 1024 * std::stod(MEMORY_GUARD_LIMIT_GB);
  if (peak_memory_is_the_runs_own) {
    EXPECT_LE(summary["peak_memory_MB"].get<double>(), limit_mb)
        << "the scale the guard proposed did not fit";
  }
  // The element estimate is the guard's basis: within the 30 % the issue asks of it.
  const double est = summary["memory_guard"]["estimated_tetrahedra"].get<double>();
  const double actual = summary["elements"].get<double>();
  EXPECT_NEAR(est / actual, 1.0, 0.3) << est << " estimated, " << actual << " meshed";
}

TEST(MemoryGuard, ANonPositiveLimitIsABadOption) {
  const auto r =
      run_cli("solve " + magfem::test::example("3d/magnetized_sphere.yaml") + " --max-memory 0");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("--max-memory"), std::string::npos) << r.out;
}

namespace {

nlohmann::json summary_of(const fs::path& out) {
  std::stringstream text;
  text << std::ifstream(out / "summary.json").rdbuf();
  return nlohmann::json::parse(text.str());
}

// sweep.csv as numbers, row by row.
std::vector<std::vector<double>> csv_numbers(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line); // header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    rows.emplace_back();
    for (std::string cell; std::getline(cells, cell, ',');)
      rows.back().push_back(std::stod(cell));
  }
  return rows;
}

// Two magnet spheres, the smaller one in group `arm`, meshed coarsely at order 1.
std::string two_spheres_case() {
  return magfem::test::write_temp_case("guard_two_spheres.yaml", R"(title: two spheres, coarse
dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.2, mu_r: 1.0}
regions:
  - {name: fixed, shape: spherical_segment, r_outer: 5, material: pm,
     magnetization: {type: parallel, direction: [0, 0, 1]}, mesh_size: 2.5}
  - {name: moving, shape: spherical_segment, r_outer: 4, material: pm,
     magnetization: {type: parallel, direction: [1, 0, 0]},
     placement: {translate: [0, 0, 14]}, group: arm, mesh_size: 2.5}
boundary: {type: open, radius: 40}
mesh: {size: 8, chord_tolerance: 0.2, probe_size: 2}
solver: {order: 1}
)");
}

} // namespace

// sweep --jobs against the guard (issue 15): FE positions that run at once each hold their own
// mesh and matrix, so W of them need W times the memory one position was checked for. A
// limit that holds one position but not two (1.7 x the estimate of one: above the 1.1 the
// sweep asks per position, its margin for the other positions' meshes, below 2 x 1.1) runs
// the positions one at a time instead, and says so; the results are those of the parallel
// run under a wide limit and the measured peak stays within the limit (two at once measured
// 180 MB against 146 MB allowed, one at a time 112 MB). Without the reduction both positions
// would run at once (jobs.used 2), each passing its own check against the whole limit.
TEST(MemoryGuard, ASweepRunsOnlyAsManyFePositionsAtOnceAsTheLimitHolds) {
  const std::string case_file = two_spheres_case();
  const fs::path wide_out = fs::temp_directory_path() / "magfem_tests" / "guard_sweep_wide";
  const fs::path held_out = fs::temp_directory_path() / "magfem_tests" / "guard_sweep_held";
  fs::remove_all(wide_out);
  fs::remove_all(held_out);
  const std::string sweep =
      "sweep " + case_file + " --rotate arm --axis y --angles 0,90 --jobs 2 --quiet";

  const auto wide = run_cli(sweep + " --max-memory 64 --out " + wide_out.string());
  ASSERT_EQ(wide.status, 0) << wide.out;
  const auto wide_summary = summary_of(wide_out);
  ASSERT_EQ(wide_summary["jobs"]["used"], 2) << "64 GB holds both positions";
  const double position_mb = wide_summary["jobs"]["estimated_position_memory_MB"].get<double>();
  ASSERT_GT(position_mb, 50) << "more than the base a run needs before any element";

  const double limit_gb = 1.7 * position_mb / 1024;
  const auto held =
      run_cli(sweep + " --max-memory " + std::to_string(limit_gb) + " --out " + held_out.string());
  ASSERT_EQ(held.status, 0) << held.out;
  EXPECT_NE(held.out.find("--jobs 2 reduced to 1"), std::string::npos) << held.out;
  EXPECT_NE(held.out.find("--max-memory"), std::string::npos) << held.out;
  const auto held_summary = summary_of(held_out);
  EXPECT_EQ(held_summary["jobs"]["requested"], 2);
  EXPECT_EQ(held_summary["jobs"]["used"], 1);
  if (peak_memory_is_the_runs_own) {
    EXPECT_LE(held_summary["peak_memory_MB"].get<double>(), 1024 * limit_gb)
        << "one position at a time stays within the limit";
  }

  // The same positions, solved one at a time: the same forces and torques (each position's
  // mesh and solve do not depend on what runs beside it; 1e-9 for the assembly's thread count).
  const auto a = csv_numbers(wide_out / "sweep.csv"), b = csv_numbers(held_out / "sweep.csv");
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), a.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t k = 0; k < a[i].size(); ++k)
      EXPECT_NEAR(b[i][k], a[i][k], 1e-9 * (std::abs(a[i][k]) + 1e-6))
          << "row " << i << ", column " << k;
}

// A sweep whose every position needs more than the limit (one position alone does not fit) is
// bad input, exit 2 before any position runs, naming --max-memory and the --mesh-scale that
// fits, as solve does; it used to run every position into the guard and exit 3.
TEST(MemoryGuard, ASweepWhosePositionsCannotFitIsRefusedBeforeItRuns) {
  const fs::path out = fs::temp_directory_path() / "magfem_tests" / "guard_sweep_refused";
  fs::remove_all(out);
  const auto r = run_cli("sweep " + two_spheres_case() +
                         " --rotate arm --axis y --angles 0,90 --jobs 2 --quiet --max-memory "
                         "0.02 --out " +
                         out.string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("--max-memory"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--mesh-scale"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("position"), std::string::npos) << "no position ran: " << r.out;
  EXPECT_FALSE(fs::exists(out / "sweep.csv")) << "nothing is written";
  EXPECT_FALSE(fs::exists(out / ".magfem-checkpoint.jsonl")) << "no checkpoint is left";
}

// Planar and axisymmetric cases: the guard counts the mesh's triangles before assembly (2D
// meshing is cheap). The RE25 motor at order 2, mesh scale 0.5 (69k triangles, 160 MB
// measured) is refused under the 77 MB limit with exit 2 naming --max-memory and nothing
// written; the --mesh-scale it names runs within the limit, and there the estimate is within
// 30 % of the measured peak (the 3D guard's bound; the 2D model's spread over its 14
// calibration runs is -7..+22 %, docs/performance.md). Peak: summary.json peak_memory_MB, the
// process's getrusage maximum resident set, as `time -f %M` measures it. Would fail on the
// guard skipped in 2D, the overrides' limit not reaching it, the scale's n / s^2 law inverted,
// or the estimate's factor dropped.
TEST(MemoryGuard, APlanarCaseOverTheLimitIsRefusedAfterMeshingAndTheProposedScaleFits) {
  const fs::path out = fs::temp_directory_path() / "magfem_tests" / "memory_guard_2d";
  fs::remove_all(out);
  const std::string base = "solve " + magfem::test::example("2d/re25_motor.yaml") +
                           " --order 2 --quiet --max-memory " MEMORY_GUARD_LIMIT_GB " --out " +
                           out.string();
  const auto refused = run_cli(base + " --mesh-scale 0.5");
  ASSERT_EQ(refused.status, 2) << refused.out;
  EXPECT_NE(refused.out.find("--max-memory"), std::string::npos) << refused.out;
  EXPECT_NE(refused.out.find("triangles"), std::string::npos) << refused.out;
  EXPECT_FALSE(fs::exists(out)) << "nothing is written";
  std::smatch m;
  ASSERT_TRUE(std::regex_search(refused.out, m, std::regex("--mesh-scale ([0-9.]+) would fit")))
      << refused.out;
  const double scale = std::stod(m[1]);
  EXPECT_GT(scale, 0.5) << "a coarser mesh fits, not a finer one";

  const auto fits = run_cli(base + " --mesh-scale " + std::string(m[1]));
  ASSERT_EQ(fits.status, 0) << fits.out;
  const auto summary = summary_of(out);
  const double peak = summary["peak_memory_MB"].get<double>();
  const double estimate = summary["memory_guard"]["estimated_peak_memory_MB"].get<double>();
  std::printf("2D guard: scale %.3g, %d triangles, estimated %.0f MB, measured peak %.0f MB\n",
              scale, summary["elements"].get<int>(), estimate, peak);
  if (peak_memory_is_the_runs_own) {
    EXPECT_LE(peak, 1024 * std::stod(MEMORY_GUARD_LIMIT_GB)) << "the proposed scale did not fit";
    EXPECT_NEAR(estimate / peak, 1.0, 0.3);
  }
}

// Planar and axisymmetric sweeps check their first position before any runs: exit 2 naming
// --max-memory, nothing written (a 10 MB limit is below any run's base: no scale fits).
TEST(MemoryGuard, PlanarAndAxisymmetricSweepsOverTheLimitAreRefusedBeforeTheyRun) {
  const fs::path out = fs::temp_directory_path() / "magfem_tests" / "memory_guard_2d_sweep";
  for (const std::string& args :
       {"sweep " + magfem::test::example("2d/diametric_pair_translate.yaml") +
            " --move mover --axis x --positions 0,5",
        "sweep " + magfem::test::example("2d/re25_motor_torque.yaml") +
            " --rotate rotor --axis z --angles 0,10",
        "sweep " + magfem::test::example("axi/magnet_over_plate.yaml") +
            " --move magnet --axis z --positions 0,1"}) {
    fs::remove_all(out);
    const auto r = run_cli(args + " --max-memory 0.01 --quiet --out " + out.string());
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
    EXPECT_NE(r.out.find("--max-memory"), std::string::npos) << args << "\n" << r.out;
    EXPECT_FALSE(fs::exists(out / "sweep.csv")) << args << ": nothing is written";
    EXPECT_FALSE(fs::exists(out / ".magfem-checkpoint.jsonl")) << args << ": no checkpoint";
  }
}
