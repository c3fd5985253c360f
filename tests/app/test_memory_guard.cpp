// The memory guard (app/memory_guard.hpp) through the binary: a 3D case whose estimated peak
// memory exceeds --max-memory stops with exit 2 before meshing, writes nothing, and names a
// --mesh-scale; that scale does fit: the run it proposes passes the guard and its measured
// peak memory stays under the limit (the estimate's calibration, README "Memory guard").
// The case is a box magnet: flat faces, so no chord limit stops the mesh from coarsening.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include "case_helpers.hpp"
#include "run_cli.hpp"

namespace fs = std::filesystem;

namespace {

using magfem::test::run_cli;
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
  EXPECT_LE(summary["peak_memory_MB"].get<double>(), limit_mb)
      << "the scale the guard proposed did not fit";
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
